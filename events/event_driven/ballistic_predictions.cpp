// The prediction interface for ballistic flights (straight, and under gravity): exact pair,
// wall and cell-crossing times, all roots of quadratics.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/roots.hpp"
#include "events/event_driven/engine.hpp"
#include "events/event_driven/pair_batch.hpp"

namespace carom {

double EventDrivenEngine::wall_time(std::int32_t i, const Wall& wall) const {
  const HotState& p = hot_[i];
  return p.clock +
         ballistic_wall_contact(wall, p.position, p.velocity, p.radius, system_.flight.gravity);
}

Event EventDrivenEngine::cell_crossing(std::int32_t i) const {
  Event best;
  const HotState& p = hot_[i];
  const Vec3 lower = grid_.cell_lower(i), upper = grid_.cell_upper(i);
  const Vec3& r = p.position;
  const Vec3& v = p.velocity;
  const Vec3& g = system_.flight.gravity;
  for (int k = 0; k < 3; ++k) {
    if (!grid_.is_outer_face(i, k, +1)) {
      const double t = p.clock + first_upward_crossing(0.5 * g[k], v[k], r[k] - upper[k]);
      if (t < best.time) best = Event{t, 2 * k + 1, 0, EventKind::CellCrossing};
    }
    if (!grid_.is_outer_face(i, k, -1)) {
      const double t = p.clock + first_upward_crossing(-0.5 * g[k], -v[k], lower[k] - r[k]);
      if (t < best.time) best = Event{t, 2 * k, 0, EventKind::CellCrossing};
    }
  }
  return best;
}

Event EventDrivenEngine::straight_cell_crossing(std::int32_t i) const {
  // On each axis only the face ahead can be reached: at s = -C / B (clamped at 0) with
  // B = |v_k| and C the signed distance past that face, which is first_upward_crossing's linear
  // case operation for operation (so the same time bit for bit: -(r - lower) is lower - r
  // exactly). Here without branches: which face, and whether the axis wins, depend on the
  // velocity and were mispredicted often. Selects are table lookups, minima are min().
  static constexpr double kSign[2] = {-1.0, 1.0};
  const HotState& p = hot_[i];
  const Vec3 bound[2] = {grid_.cell_lower(i), grid_.cell_upper(i)};
  double best_time = kNever;
  int best_face = -1;
  for (int k = 0; k < 3; ++k) {
    const double v = p.velocity[k];
    const int up = v > 0.0;
    const double B = std::abs(v);
    const double C = kSign[up] * (p.position[k] - bound[up][k]);
    const double s = std::max(-C / B, 0.0);
    const bool outer[2] = {grid_.is_outer_face(i, k, -1), grid_.is_outer_face(i, k, +1)};
    const int open = (B > 0.0) & !outer[up];
    const double time[2] = {kNever, p.clock + s};
    const double t = time[open];
    const int earlier = t < best_time;  // strictly: the first axis of equal times
    best_face += earlier * (2 * k + up - best_face);
    best_time = std::min(best_time, t);
  }
  return best_face < 0 ? Event{} : Event{best_time, best_face, 0, EventKind::CellCrossing};
}

template <>
void EventDrivenEngine::plan<StraightFlights>(std::int32_t i, bool new_trajectory) {
  if (new_trajectory) agenda_[i].crossing = straight_cell_crossing(i);
  plan_ballistic<false>(i);
}

template <>
void EventDrivenEngine::plan<GravityFlights>(std::int32_t i, bool new_trajectory) {
  if (new_trajectory) agenda_[i].crossing = cell_crossing(i);
  plan_ballistic<true>(i);
}

template <>
void EventDrivenEngine::predict_after_crossing<StraightFlights>(std::int32_t i, int axis, int direction) {
  scan_slab<false>(i, axis, direction);
}

template <>
void EventDrivenEngine::predict_after_crossing<GravityFlights>(std::int32_t i, int axis, int direction) {
  scan_slab<true>(i, axis, direction);
}

template <bool kGravity>
void EventDrivenEngine::plan_ballistic(std::int32_t i) {
  Event best;
  for (std::size_t w = 0; w < system_.walls.size(); ++w) {
    const double t = wall_time(i, system_.walls[w]);
    if (t < best.time) best = Event{t, static_cast<std::int32_t>(w), 0, EventKind::Wall};
  }
  // Own level: the block around i's cell, without periodic images unless it wraps.
  std::int32_t cells[HierarchicalGrid::kMaxBlock];
  bool wrapped = false;
  const int count = grid_.own_block(i, cells, wrapped);
  double best_pair_time = best.time;
  const std::int32_t best_partner =
      scan_cells<kGravity>(i, grid_.level_of(i), cells, count, wrapped, best_pair_time,
                           memo_.empty() ? nullptr : &memo_[i]);
  if (best_partner >= 0)
    best = Event{best_pair_time, best_partner, counter_[best_partner], EventKind::Pair};
  if (grid_.levels().size() > 1) scan_other_levels<kGravity>(i, best);
  agenda_[i].collision = best;
}

template <bool kGravity>
void EventDrivenEngine::scan_other_levels(std::int32_t i, Event& best, int axis,
                                          int direction) const {
  const int own = grid_.level_of(i);
  const auto& levels = grid_.levels();
  for (int level = 0; level < static_cast<int>(levels.size()); ++level) {
    if (level == own) continue;
    // The same candidates in the same order as one pair test at a time (the first of equal
    // times wins), batched as on the own level.
    auto scan_into = [&](Event& into) {
      return [&, level](const std::int32_t* cells, int count, bool wrapped) {
        double time = into.time;
        const std::int32_t partner = scan_cells<kGravity>(i, level, cells, count, wrapped, time);
        if (partner >= 0) into = Event{time, partner, counter_[partner], EventKind::Pair};
      };
    };
    if (direction != 0) {
      grid_.for_each_entering_piece(i, level, axis, direction, scan_into(best));
    } else if (!kGravity && options_.skip_unreachable_cells && walks_far_into(own, level)) {
#ifndef NDEBUG
      Event unskipped = best;
      grid_.for_each_covering_piece(i, level, scan_into(unskipped));
#endif
      scan_finer_level_near(i, level, best, scan_into(best));
      // The oracle: the same earliest contact as the walk of every covering cell, bit for bit
      // (of equal times either partner may come first).
      assert(unskipped.time == best.time);
    } else {
      grid_.for_each_covering_piece(i, level, scan_into(best));
    }
  }
}

bool EventDrivenEngine::walks_far_into(int own, int level) const {
  // Cells along an axis of the other level's block: the two passes of scan_finer_level_near
  // paid for carom_bench's 1:10 fines (8.3 cells: 1.06-1.17 times as fast, medians of three
  // sets) and not for its 1:5 (5.7 cells: 0.965; tests/bench/README.md).
  constexpr double kFarFrom = 7.0;
  const auto& levels = grid_.levels();
  if (!(levels[level].max_radius < levels[own].max_radius)) return false;
  const double across = levels[own].cell_size.minCoeff() + 2.0 * grid_.reach_between(own, level);
  return across >= kFarFrom * levels[level].cell_size.maxCoeff();
}

template <class Scan>
void EventDrivenEngine::scan_finer_level_near(std::int32_t i, int level, const Event& best,
                                              Scan&& scan) const {
  // At the last particle event t0 every particle lies in its cell (up to round-off: each is
  // moved on at its crossing). A straight flight j of `level` can touch i before `best` only if
  // their distance at t0 is at most the two radii and what both fly until then, |v_i| + |v_j|
  // times (best - t0), and |v_j| is at most that level's bound. So a cell farther from i's
  // position at t0 than r_i + r_max + (|v_i| + v_max) (best - t0) holds no particle whose contact
  // comes before `best`: it is skipped. Taken 1e-9 wider, with a margin of 1e-9 of a cell for
  // positions on a cell's face, far above the round-off of either side, so that a contact at
  // `best` itself is never skipped: the event's time is that of the walk of every covering cell
  // (the debug build checks each one). As `best` comes nearer with each partner found, the walk
  // skips more; the cells within touching distance of i come first (they hold the likely
  // earliest partners: 214 cells and 75 candidates walked of 729 and 306, for the large spheres
  // of carom_bench's 1:10 fines; tests/bench/README.md), so of equal times the first in that
  // order wins. That order does not depend on the bound, and the bound skips only cells that
  // hold no contact up to `best`: the same state gives the same event whatever the bound.
  constexpr double kWiden = 1.0 + 1e-9, kFaceMargin = 1e-9;
  const HotState& a = hot_[i];
  const HierarchicalGrid::Level& finer = grid_.levels()[level];
  const double t0 = last_particle_event_;
  const Vec3 p = a.position + (t0 - a.clock) * a.velocity;
  const double at_rest = a.radius + finer.max_radius;
  const double speeds = a.velocity.norm() + std::sqrt(level_speed2_[level]);
  const double margin = kFaceMargin * finer.cell_size.maxCoeff();
  auto within = [&] {
    if (best.time == kNever) return kNever;
    return (at_rest + speeds * std::max(0.0, best.time - t0)) * kWiden + margin;
  };
  grid_.for_each_covering_piece_near(i, level, p, at_rest, within, scan);
}

double EventDrivenEngine::scheduled_time(std::int32_t i) {
  // Round-off may put a root a hair before the last event: nothing happens in the past.
  Agenda& a = agenda_[i];
  if (a.collision.time < last_particle_event_) a.collision.time = last_particle_event_;
  if (a.crossing.time < last_particle_event_) a.crossing.time = last_particle_event_;
  return next_event(i).time;
}

void EventDrivenEngine::schedule(std::int32_t i) {
  calendar_.set(static_cast<std::size_t>(i), scheduled_time(i));
}

template <bool kGravity>
std::int32_t EventDrivenEngine::scan_cells(std::int32_t i, int level, const std::int32_t* cells,
                                           int count, bool wrapped, double& best_time,
                                           CandidateMemo* memo) const {
  const HotState& a = hot_[i];
  const PairQuery query{a.position, a.velocity, a.clock, a.radius, system_.flight.gravity,
                        system_.domain};
  const HotState padding = query.never_touching();
  const HotState* hot = hot_.data();
  const std::int32_t* head = grid_.head_array(level);
  const std::int32_t* next = grid_.next_array();
  std::int32_t best_partner = -1;
  // Candidates are gathered into a batch, their contact times computed four at a time, and the
  // earliest picked in the order the cells were walked (as one at a time would: the first of
  // equal times). Two list places without a branch: the dense fluid's cells hold 0-2 (a
  // settling bed of fines walked four gained 1.4 %, the fluid lost 12 %; tests/bench/README.md).
  PairBatch batch;
  auto test = [&](int found) {
    if (memo != nullptr) {  // the first batch's candidates: the walk's first kSize
      memo->remember(i, batch, found, hot);
      memo = nullptr;
    }
    batch.pad_to_vectors(found, &padding);
    if (wrapped)
      contact_times<kGravity, true>(query, batch);
    else
      contact_times<kGravity, false>(query, batch);
    const int k = batch.earliest;
    if (k >= 0 && batch.time[k] < best_time) {
      best_time = batch.time[k];
      best_partner = static_cast<std::int32_t>(batch.state[k] - hot);
    }
  };
  if (prefetching())
    gather_candidates<2, true>(i, head, next, cells, count, hot, batch, test, counter_.data());
  else
    gather_candidates<2>(i, head, next, cells, count, hot, batch, test);
  return best_partner;
}

template <bool kGravity>
void EventDrivenEngine::scan_slab(std::int32_t i, int axis, int direction) {
  agenda_[i].crossing = kGravity ? cell_crossing(i) : straight_cell_crossing(i);
  std::int32_t cells[HierarchicalGrid::kMaxBlock];
  bool wrapped = false;
  const int count = grid_.own_slab(i, axis, direction, cells, wrapped);
  double best_pair_time = agenda_[i].collision.time;
  const std::int32_t best_partner =
      scan_cells<kGravity>(i, grid_.level_of(i), cells, count, wrapped, best_pair_time);
  if (best_partner >= 0)
    agenda_[i].collision =
        Event{best_pair_time, best_partner, counter_[best_partner], EventKind::Pair};
  if (grid_.levels().size() > 1)
    scan_other_levels<kGravity>(i, agenda_[i].collision, axis, direction);
  schedule(i);
}

template void EventDrivenEngine::scan_slab<true>(std::int32_t, int, int);
template void EventDrivenEngine::scan_slab<false>(std::int32_t, int, int);

template void EventDrivenEngine::plan_ballistic<true>(std::int32_t);
template void EventDrivenEngine::plan_ballistic<false>(std::int32_t);

}  // namespace carom
