// Processing of particle events: pair and wall collisions, cell crossings, the invariant checks
// and the collapse detector's bookkeeping.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "events/event_driven/engine.hpp"
#include "events/laws/effective_law.hpp"
#include "events/laws/walton.hpp"

namespace carom {

template <class Flight>
void EventDrivenEngine::collide_pair(std::int32_t i, std::int32_t j, double t) {
  last_particle_event_ = time_ = t;
  advance<Flight>(i, t);
  advance<Flight>(j, t);
  HotState& mi = hot_[i];
  HotState& mj = hot_[j];
  Body& bi = body_[i];
  Body& bj = body_[j];
  Vec3 dr = mi.position - mj.position;
  system_.domain.minimum_image(dr);
  const double distance = dr.norm();
  const Vec3 n = dr / distance;
  const ParticleStore& p = system_.particles;
  const Vec3 momentum_before = options_.check_invariants
                                   ? Vec3(p.mass[i] * mi.velocity + p.mass[j] * mj.velocity)
                                   : Vec3::Zero();
  const std::uint32_t si = bi.species, sj = bj.species;
  const double normal_velocity = (mi.velocity - mj.velocity).dot(n);  // < 0: approaching
  const ContactLaw law = effective_law(system_.materials.pair(si, sj), options_.collapse,
                                       normal_velocity, t, bi.last_collision, bj.last_collision);
  const CollisionOutcome outcome =
      collide(law, n,
              ContactBody{mi.velocity, bi.spin, bi.fixed ? 0.0 : bi.inverse_mass, mi.radius,
                          bi.fixed ? 0.0 : bi.inverse_inertia},
              ContactBody{mj.velocity, bj.spin, bj.fixed ? 0.0 : bj.inverse_mass, mj.radius,
                          bj.fixed ? 0.0 : bj.inverse_inertia});
  if (options_.check_invariants && !bi.fixed && !bj.fixed)
    check_pair_invariants(i, j, momentum_before);
  note_speed<Flight>(i);
  note_speed<Flight>(j);

  const std::size_t species = statistics_.species_count;
  statistics_.count_pair(si, sj, system_.is_impact(-normal_velocity));
  const double impulse = outcome.impulse.norm();
  statistics_.pair_impulse[si * species + sj] += impulse;
  if (si != sj) statistics_.pair_impulse[sj * species + si] += impulse;
  statistics_.virial += dr * outcome.impulse.transpose();
  statistics_.dissipated_energy += outcome.dissipated;
  if (statistics_.tagged.any()) statistics_.tagged.book_pair(i, j, si, sj, outcome.impulse);
  ++counter_[i];
  ++counter_[j];
  // j's place has arrived by now (prefetch_pair): its cells' first particles load while i is
  // predicted.
  if (prefetching()) grid_.prefetch_own_block(j);
  // j's memo was hinted with the event (prefetch_event): its candidates load while i is predicted.
  if (remembers_candidates<Flight>()) memo_[j].hint(j, hot_.data(), grid_.next_array(), counter_.data());
  predict_pair<Flight>(i, j);
  book_collision(i, t, j);
  book_collision(j, t, i);
  bi.last_collision = bj.last_collision = t;
}

template <class Flight>
void EventDrivenEngine::collide_wall(std::int32_t i, std::int32_t w, double t) {
  last_particle_event_ = time_ = t;
  advance<Flight>(i, t);
  HotState& m = hot_[i];
  Body& b = body_[i];
  const Wall& wall = system_.walls[w];
  const Vec3 n = wall.contact_normal(m.position);
  if (options_.check_invariants && wall.gap(m.position, m.radius) < -1e-10 * m.radius) {
    std::ostringstream out;
    out << "invariant broken: particle " << system_.particles.id[i] << " overlaps wall '"
        << wall.name << "' by " << -wall.gap(m.position, m.radius) << " m at t = " << t << " s";
    throw std::logic_error(out.str());
  }
  const std::uint32_t si = b.species;
  const double normal_velocity = m.velocity.dot(n);  // < 0: approaching
  const ContactLaw law = effective_law(system_.materials.wall(si, w), options_.collapse,
                                       normal_velocity, t, b.last_collision, -kNever);
  Vec3 wall_velocity = Vec3::Zero(), wall_spin = Vec3::Zero();
  const CollisionOutcome outcome =
      collide(law, n, ContactBody{m.velocity, b.spin, b.inverse_mass, m.radius, b.inverse_inertia},
              ContactBody{wall_velocity, wall_spin, 0.0, 0.0, 0.0});
  note_speed<Flight>(i);
  statistics_.count_wall(si, w, system_.is_impact(-normal_velocity));
  statistics_.wall_impulse[w] -= outcome.impulse;
  statistics_.dissipated_energy += outcome.dissipated;
  if (statistics_.tagged.any()) statistics_.tagged.book_wall(i, w, outcome.impulse);
  ++counter_[i];
  predict<Flight>(i);
  book_collision(i, t, -1 - w);
  b.last_collision = t;
}

template <class Flight>
void EventDrivenEngine::cross_cell(std::int32_t i, int face) {
  const int axis = face / 2, direction = (face % 2) ? +1 : -1;
  // Bring the stored state to the crossing: the next crossing is then predicted from "now"
  // (a particle that fell back through a face is not mistaken for one still rising), and
  // stored states never lag more than one cell behind (so one periodic image shift suffices).
  advance<Flight>(i, time_);
  hot_[i].position += grid_.cross(i, axis, direction);  // a periodic wrap: one box length
  note_cell_entered<Flight>(i);                         // into its new cell
  ++statistics_.cell_crossings;
  // Same trajectory: partners' predictions with i stay valid (no counter bump), and so does
  // i's own next collision.
  predict_after_crossing<Flight>(i, axis, direction);
}

void EventDrivenEngine::book_collision(std::int32_t i, double t, std::int32_t partner_code) {
  if (rate_.due(statistics_.pair_events, statistics_.wall_events, t)) {
    const double span = t - rate_.start_time;
    const double frequency =
        rate_.measure(statistics_.pair_events, statistics_.wall_events, t, agenda_.size());
    if (frequency > rate_.limit)
      throw MethodFailure("lasting_contacts",
                          lasting_contact_diagnostic(t, frequency, span, options_.collapse));
  }
  StallRecord& record = agenda_[i].stall;
  if (!stall_.book(record, t)) return;
  const ParticleStore& p = system_.particles;
  const std::string partner = partner_code >= 0
                                  ? "particle " + std::to_string(p.id[partner_code])
                                  : "wall '" + system_.walls[-1 - partner_code].name + "'";
  std::vector<std::uint64_t> ids{p.id[i]};
  if (partner_code >= 0) ids.push_back(p.id[partner_code]);
  throw InelasticCollapse(
      collapse_diagnostic(t, describe(i), record.count, t - record.window_start, partner,
                          options_.collapse),
      ids);
}

void EventDrivenEngine::check_pair_invariants(std::int32_t i, std::int32_t j,
                                              const Vec3& momentum_before) const {
  const ParticleStore& p = system_.particles;
  const HotState& mi = hot_[i];
  const HotState& mj = hot_[j];
  Vec3 dr = mi.position - mj.position;
  system_.domain.minimum_image(dr);
  const double contact = mi.radius + mj.radius;
  const Vec3 momentum_after = p.mass[i] * mi.velocity + p.mass[j] * mj.velocity;
  const double scale =
      p.mass[i] * mi.velocity.norm() + p.mass[j] * mj.velocity.norm() + momentum_before.norm();
  std::ostringstream out;
  if (dr.norm() < contact * (1.0 - 1e-10))
    out << "particles " << p.id[i] << " and " << p.id[j] << " overlap by " << contact - dr.norm() << " m";
  else if ((momentum_after - momentum_before).norm() > 1e-13 * scale)
    out << "momentum not conserved in collision of " << p.id[i] << " and " << p.id[j];
  else
    return;
  throw std::logic_error("invariant broken at t = " + std::to_string(time_) + " s: " + out.str());
}

#define CAROM_INSTANTIATE_COLLISIONS(Flight)                                             \
  template void EventDrivenEngine::collide_pair<Flight>(std::int32_t, std::int32_t, double); \
  template void EventDrivenEngine::collide_wall<Flight>(std::int32_t, std::int32_t, double); \
  template void EventDrivenEngine::cross_cell<Flight>(std::int32_t, int);
CAROM_INSTANTIATE_COLLISIONS(StraightFlights)
CAROM_INSTANTIATE_COLLISIONS(GravityFlights)
CAROM_INSTANTIATE_COLLISIONS(RelaxFlights)
#undef CAROM_INSTANTIATE_COLLISIONS

}  // namespace carom
