// The prediction interface for relax flights (gravity plus a linear drag frozen for one fluid
// step): pairs, walls, the cylinder and grid cells. Nothing is predicted past the next fluid step
// (horizon_), where every particle is synchronised and predicted again.
#include <algorithm>
#include <bit>
#include <cassert>

#include "core/relax_roots.hpp"
#include "events/event_driven/engine.hpp"
#include "events/event_driven/reach_cells.hpp"

namespace carom {

namespace {
/// List places a prediction takes without a branch (gather_candidates): two where a cell holds
/// about one particle, four where lists are long (fines among large spheres in a 1 mm cell), and
/// the list length seen (HierarchicalGrid::list_length_seen) from which the deeper walk pays.
constexpr int kShortListWalk = 2;
constexpr int kLongListWalk = 4;
constexpr double kLongLists = 2.5;
/// Fluid steps between two measurements of the list lengths (predict_all).
constexpr std::uint64_t kListsEvery = 64;

/// reach_tests<image, lines>, chosen at run time.
std::uint64_t reach_tests(const ReachQuery& query, const PairBatch& batch, bool image, bool lines) {
  if (image)
    return lines ? reach_tests<true, true>(query, batch) : reach_tests<true, false>(query, batch);
  return lines ? reach_tests<false, true>(query, batch) : reach_tests<false, false>(query, batch);
}
}  // namespace

double EventDrivenEngine::relax_pair_time(std::int32_t i, std::int32_t j, double limit,
                                          const RelaxMotion& motion_i) const {
  const HotState& a = hot_[i];
  const HotState& b = hot_[j];
  const RelaxFlight& fa = flights_[i];
  const RelaxFlight& fb = flights_[j];
  // Both states at the later of the two clocks.
  const double t_ref = a.clock > b.clock ? a.clock : b.clock;
  const double end = std::min(horizon_, limit);
  const double horizon = end - t_ref;
  if (!(horizon > 0.0)) return kNever;
  const double contact = a.radius + b.radius;
  // Two exact rejections, and the contact search only when neither ends the candidate (in
  // either order: the search runs for the same candidates, so every event is the same).
  //
  // The sweep test: a particle flying from its clock to `end` stays within
  // |v0| s + |a0| s^2 / 2 of where it was (its acceleration only decays, see relax_flight.hpp).
  // Two such balls that do not reach each other cannot touch. Before either state is advanced
  // (which costs exponentials), this is the cheapest test, and in a dense bed it ends most
  // candidates.
  auto out_of_sweep = [&] {
    const double span_a = end - a.clock, span_b = end - b.clock;
    const double sweep =
        span_a * (motion_i.speed + 0.5 * span_a * motion_i.acceleration) +
        span_b * (b.velocity.norm() + 0.5 * span_b * fb.acceleration(b.velocity).norm());
    Vec3 gap = a.position - b.position;
    system_.domain.minimum_image(gap);
    const double reach = contact + sweep;
    return gap.squaredNorm() > reach * reach;
  };
  // States on the same clock (every prediction right after a fluid step: two thirds of a
  // bubbling bed's) need no advancing, and then the line test below goes first: it ends far
  // more (counted on the bubbling bed to 0.3 s, before the line test of the stored states: of
  // 17.8 million candidates the reach test let through, the sweep test ended 16 %, the line
  // test 79 % of the rest; lines_apart now ends most of those before they come here).
  const bool same_clock = a.clock == b.clock;
  if (!same_clock && out_of_sweep()) return kNever;
  const double dt_a = t_ref - a.clock, dt_b = t_ref - b.clock;
  Vec3 dr = a.position - b.position;
  Vec3 va = a.velocity, vb = b.velocity;
  if (dt_a > 0.0) {
    dr += fa.displacement(a.velocity, dt_a);
    va = fa.velocity(a.velocity, dt_a);
  }
  if (dt_b > 0.0) {
    dr -= fb.displacement(b.velocity, dt_b);
    vb = fb.velocity(b.velocity, dt_b);
  }
  system_.domain.minimum_image(dr);
  // The line test: each acceleration only decays (a(s) = a(0) e^{-rate s}), so the relative
  // path strays from the straight line dr + u s by at most A s^2 / 2 with
  // A = |a_a(0)| + |a_b(0)|. If that line keeps farther than contact + A H^2 / 2 from the origin
  // over [0, H], the spheres cannot touch (lines_apart's test on the states advanced exactly,
  // with the exact accelerations: the candidates it ends that lines_apart let through).
  const Vec3 u = va - vb;
  const double accel = (dt_a > 0.0 ? fa.acceleration(va).norm() : motion_i.acceleration) +
                       fb.acceleration(vb).norm();
  const double reach = contact + 0.5 * accel * horizon * horizon;
  const double u2 = u.squaredNorm();
  const double closest = u2 > 0.0 ? std::clamp(-dr.dot(u) / u2, 0.0, horizon) : 0.0;
  if ((dr + closest * u).squaredNorm() > reach * reach) return kNever;
  if (same_clock && out_of_sweep()) return kNever;
  // Half the pairs left are in contact (or nearly) and separate: ended without the search.
  if (options_.relax_pair_shortcuts && relax_pair_separating(dr, va, fa, vb, fb, horizon))
    return kNever;
  const double s = relax_pair_contact_time(dr, va, fa, vb, fb, contact, horizon);
  return s == kNever ? kNever : t_ref + s;
}

double EventDrivenEngine::relax_wall_time(std::int32_t i, const Wall& wall, double limit) const {
  const HotState& p = hot_[i];
  const double horizon = std::min(horizon_, limit) - p.clock;
  if (!(horizon > 0.0)) return kNever;
  const double s = relax_wall_contact(wall, p.position, p.velocity, p.radius, flights_[i], horizon);
  return s == kNever ? kNever : p.clock + s;
}

Event EventDrivenEngine::relax_cell_crossing(std::int32_t i) const {
  Event best;
  const HotState& p = hot_[i];
  const RelaxFlight& f = flights_[i];
  const double horizon = horizon_ - p.clock;
  const Vec3 lower = grid_.cell_lower(i), upper = grid_.cell_upper(i);
  for (int k = 0; k < 3; ++k) {
    // The gap to the upper face closes at -v_k; its "drive" is -drive_k (see relax_roots.hpp).
    if (!grid_.is_outer_face(i, k, +1)) {
      const double s = relax_gap_closing_time(upper[k] - p.position[k], -p.velocity[k], -f.drive[k],
                                              f.rate, horizon);
      if (s != kNever && p.clock + s < best.time)
        best = Event{p.clock + s, 2 * k + 1, 0, EventKind::CellCrossing};
    }
    if (!grid_.is_outer_face(i, k, -1)) {
      const double s = relax_gap_closing_time(p.position[k] - lower[k], p.velocity[k], f.drive[k],
                                              f.rate, horizon);
      if (s != kNever && p.clock + s < best.time)
        best = Event{p.clock + s, 2 * k, 0, EventKind::CellCrossing};
    }
  }
  return best;
}

Event EventDrivenEngine::relax_collision(std::int32_t i, double limit) const {
  // Searching each candidate only up to the best time so far lets most of them stop at the
  // first bound.
  Event best;
  for (std::size_t w = 0; w < system_.walls.size(); ++w) {
    const double t = relax_wall_time(i, system_.walls[w], limit);
    if (t < best.time) {
      best = Event{t, static_cast<std::int32_t>(w), 0, EventKind::Wall};
      limit = t;
    }
  }
  // Most candidates of a dense bed are too far away to be reached before the limit. They are
  // ended by a looser form of relax_pair_time's first rejection (may_reach: the query's sweep
  // computed once per limit, the candidate's bounded from its record alone by flight_bounds_,
  // no square root), four at a time (reach_tests). What passes is decided by relax_pair_time
  // itself, so the events are the same bit for bit. (Without it, 90 % of a dense bed's
  // prediction time went to that first rejection's four square roots.)
  const HotState& a = hot_[i];
  const RelaxFlight& fa = flights_[i];
  const RelaxMotion motion = RelaxMotion::of(a, fa);
  // Of the candidates that may reach, three in four are pairs in contact that separate (a dense
  // bed): the straight lines of their stored states end them (lines_apart), before any flight
  // is read or state advanced, four at a time in the batch.
  const bool lines = options_.relax_pair_shortcuts;
  ReachQuery query{a.position, a.radius,       0.0,
                   0.0,        flight_bounds_, system_.domain,
                   a.velocity, a.clock,        motion.acceleration};
  auto set_limit = [&](double t) {
    limit = t;
    query.end = std::min(horizon_, limit);
    query.sweep = fa.reach_bound(a.velocity, query.end - a.clock);
  };
  set_limit(limit);
  // Whether candidate j's flight is within the bounds the test assumes (debug builds).
  [[maybe_unused]] auto bounded = [&](std::int32_t j) {
    return flights_[j].rate <= flight_bounds_.rate &&
           flights_[j].drive.cwiseAbs().sum() <= flight_bounds_.drive;
  };
  auto consider = [&](std::int32_t j, bool wrapped) {
    assert(bounded(j));
    const HotState& b = hot_[j];
    if (!(wrapped ? may_reach<true>(query, b) : may_reach<false>(query, b))) return;
    if (lines && (wrapped ? lines_apart<true>(query, b) : lines_apart<false>(query, b))) return;
    const double t = relax_pair_time(i, j, limit, motion);
    if (t < best.time) {
      best = Event{t, j, counter_[j], EventKind::Pair};
      set_limit(t);
    }
  };
  // The own level's candidates, gathered in the cells' order and tested in batches; those that
  // pass are considered one at a time in that order (the limit may have fallen since the batch
  // was tested, so may_reach and lines_apart are asked again with the current one, as one at
  // a time would).
  std::int32_t cells[HierarchicalGrid::kMaxBlock];
  bool wrapped = false;
  int count = grid_.own_block(i, cells, wrapped);
  // Where lists are long the cells beyond reach hold enough candidates to pay for the test of
  // each cell (the main job: the walk and the reach test fall from 24 % to 17 % of its time,
  // the test of the cells included); with lists of one or two it costs more than it saves (the
  // bubbling bed: 4 % slower).
  const bool long_lists = long_lists_ >> grid_.level_of(i) & 1u;
  if (long_lists && options_.skip_unreachable_cells)
    count = drop_unreachable_cells(i, query, cells, count, wrapped);
  const std::int32_t* head = grid_.head_array(grid_.level_of(i));
  const std::int32_t* next = grid_.next_array();
  const HotState* hot = hot_.data();
  PairBatch batch;
  auto test = [&](int found) {
    batch.pad_to_vectors(found, &a);  // the padding's answers are not read
#ifndef NDEBUG
    for (int k = 0; k < found; ++k)
      assert(bounded(static_cast<std::int32_t>(batch.state[k] - hot)));
#endif
    std::uint64_t reached = reach_tests(query, batch, wrapped, lines);
    reached &= found == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << found) - 1;
    for (; reached != 0; reached &= reached - 1)  // in the cells' order
      consider(static_cast<std::int32_t>(batch.state[std::countr_zero(reached)] - hot), wrapped);
  };
  // The same candidates in the same order either way (see gather_candidates).
  if (long_lists)
    gather_candidates<kLongListWalk>(i, head, next, cells, count, hot, batch, test);
  else
    gather_candidates<kShortListWalk>(i, head, next, cells, count, hot, batch, test);
  if (grid_.levels().size() > 1)  // their pieces may wrap: always the nearest image
    grid_.for_each_candidate_on_other_levels(i, [&](std::int32_t j) {
      if (j != i) consider(j, true);
    });
  return best;
}

int EventDrivenEngine::drop_unreachable_cells(std::int32_t i, const ReachQuery& query,
                                              std::int32_t* cells, int count,
                                              [[maybe_unused]] bool wrapped) const {
#ifndef NDEBUG
  std::int32_t block[HierarchicalGrid::kMaxBlock];
  std::copy(cells, cells + count, block);
  // What the drop assumes: every cell's bound holds its particles' speeds, and no clock is
  // earlier than speed_clock_ (note_speed after every change, reset_cell_speeds).
  const double* bound = grid_.cell_bound_array(grid_.level_of(i));
  for (int c = 0; c < count; ++c)
    for (std::int32_t j = grid_.head(grid_.level_of(i), block[c]); j >= 0; j = grid_.next(j))
      assert(RelaxFlightBounds::speed_bound(hot_[j].velocity) <= bound[block[c]] &&
             hot_[j].clock >= speed_clock_);
#endif
  const int kept = drop_cells_out_of_reach(grid_, i, query, speed_clock_, cells, count);
#ifndef NDEBUG
  // The oracle: every particle of a dropped cell fails the reach test itself.
  const int level = grid_.level_of(i);
  for (int c = 0, k = 0; c < count; ++c) {
    if (k < kept && cells[k] == block[c]) {
      ++k;
      continue;
    }
    for (std::int32_t j = grid_.head(level, block[c]); j >= 0; j = grid_.next(j))
      assert(j == i ||
             !(wrapped ? may_reach<true>(query, hot_[j]) : may_reach<false>(query, hot_[j])));
  }
#endif
  return kept;
}

void EventDrivenEngine::reset_cell_speeds() {
  grid_.clear_cell_bounds();
  speed_clock_ = time_;
  for (std::size_t i = 0; i < hot_.size(); ++i) {
    const auto k = static_cast<std::int32_t>(i);
    grid_.raise_cell_bound(k, RelaxFlightBounds::speed_bound(hot_[k].velocity));
    speed_clock_ = std::min(speed_clock_, hot_[k].clock);
  }
}

template <>
void EventDrivenEngine::plan<RelaxFlights>(std::int32_t i, bool new_trajectory) {
  if (horizon_ == kNever) {
    // No fluid step registered yet: nothing can be predicted (registering one predicts all).
    agenda_[i].collision = agenda_[i].crossing = Event{};
    return;
  }
  if (new_trajectory) agenda_[i].crossing = relax_cell_crossing(i);
  // Only events before the next crossing matter: a crossing predicts everything again (see
  // cross_cell).
  agenda_[i].collision = relax_collision(i, agenda_[i].crossing.time);
}

WorkerPool* EventDrivenEngine::shared_workers() {
  // Below a few hundred particles a loop is done before the workers would wake.
  constexpr std::size_t kShared = 256;
  if (hot_.size() < kShared || threads_ == 1) return nullptr;
  if (!workers_) workers_ = std::make_shared<WorkerPool>(threads_);
  return workers_.get();
}

namespace {
/// Predictions per piece handed out after a fluid step (a few microseconds each: a piece is
/// about a hundred microseconds, the shared counter's traffic negligible).
constexpr std::size_t kPlanChunk = 32;
}  // namespace

template <>
void EventDrivenEngine::predict_all<RelaxFlights>() {
  const std::size_t n = hot_.size();
  reset_cell_speeds();
  // The lists' lengths choose how the candidates are walked, never which or in what order: they
  // are measured at every kListsEvery-th fluid step only (a walk over every cell of the grid:
  // 16 000 cells for a bubbling bed's 2000 beads, 1 % of its time when done at every step).
  if (lists_measured_ % kListsEvery == 0) {
    long_lists_ = 0;
    for (int l = 0; l < static_cast<int>(grid_.levels().size()) && l < 32; ++l)
      if (grid_.list_length_seen(l) > kLongLists) long_lists_ |= 1u << l;
  }
  ++lists_measured_;
  // Each particle's agenda is its own cache line (Agenda is aligned to 64 bytes), and the
  // plans read only what no plan writes: any split gives the same agendas.
  auto plan_range = [this](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) plan<RelaxFlights>(static_cast<std::int32_t>(k));
  };
  WorkerPool* workers = threads_ > 2 && horizon_ != kNever ? shared_workers() : nullptr;
  if (workers != nullptr)
    workers->for_chunks(n, plan_range);
  else  // pieces taken in turn by this and the side thread (no wake-up of a sleeping pool)
    carom::for_chunks(horizon_ != kNever ? side_thread() : nullptr, n, kPlanChunk, plan_range);
  // The calendar: every particle's slot, then each block's place in the heap once (the same
  // order of events as a schedule per particle; Calendar.SetFirstIsSetOneByOne).
  calendar_.set_first(
      n, [this](std::size_t i) { return scheduled_time(static_cast<std::int32_t>(i)); });
}

template <>
void EventDrivenEngine::predict_after_crossing<RelaxFlights>(std::int32_t i, int, int) {
  // Relax trajectories are not straight relative to each other: predict everything again.
  predict<RelaxFlights>(i);
}

}  // namespace carom
