// Processing of particle events: pair and wall collisions, cell crossings, the stall detector.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "simulator.hpp"
#include "walton.hpp"

namespace carom {

ContactLaw Simulator::effective_law(const ContactLaw& law, double normal_speed, double t,
                                    std::int32_t i, std::int32_t j) const {
  const CollapseOptions& collapse = options_.collapse;
  if (collapse.contact_time > 0.0 &&
      (t - body_[i].last_collision < collapse.contact_time ||
       (j >= 0 && t - body_[j].last_collision < collapse.contact_time))) {
    ContactLaw elastic_smooth;  // e = 1, mu = 0: no energy lost, no tangential impulse
    return elastic_smooth;
  }
  if (std::abs(normal_speed) < collapse.elastic_below_speed) {
    ContactLaw elastic = law;
    elastic.restitution = 1.0;
    return elastic;
  }
  return law;
}

void Simulator::collide_pair(std::int32_t i, std::int32_t j, double t) {
  last_particle_event_ = time_ = t;
  advance(i, t);
  advance(j, t);
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
  const ContactLaw law =
      effective_law(system_.materials.pair(si, sj), (mi.velocity - mj.velocity).dot(n), t, i, j);
  const CollisionOutcome outcome =
      collide(law, n,
              ContactBody{mi.velocity, bi.spin, bi.fixed ? 0.0 : bi.inverse_mass, mi.radius,
                          bi.fixed ? 0.0 : bi.inverse_inertia},
              ContactBody{mj.velocity, bj.spin, bj.fixed ? 0.0 : bj.inverse_mass, mj.radius,
                          bj.fixed ? 0.0 : bj.inverse_inertia});
  if (options_.check_invariants && !bi.fixed && !bj.fixed)
    check_pair_invariants(i, j, momentum_before);

  const std::size_t species = statistics_.species_count;
  ++statistics_.pair_collisions[si * species + sj];
  if (si != sj) ++statistics_.pair_collisions[sj * species + si];
  const double impulse = outcome.impulse.norm();
  statistics_.pair_impulse[si * species + sj] += impulse;
  if (si != sj) statistics_.pair_impulse[sj * species + si] += impulse;
  ++statistics_.pair_events;
  statistics_.virial += dr * outcome.impulse.transpose();
  statistics_.dissipated_energy += outcome.dissipated;
  ++counter_[i];
  ++counter_[j];
  predict(i);
  predict(j);
  book_collision(i, t, j);
  book_collision(j, t, i);
  bi.last_collision = bj.last_collision = t;
}

void Simulator::collide_wall(std::int32_t i, std::int32_t w, double t) {
  last_particle_event_ = time_ = t;
  advance(i, t);
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
  const ContactLaw law = effective_law(system_.materials.wall(si, w), m.velocity.dot(n), t, i, -1);
  Vec3 wall_velocity = Vec3::Zero(), wall_spin = Vec3::Zero();
  const CollisionOutcome outcome =
      collide(law, n, ContactBody{m.velocity, b.spin, b.inverse_mass, m.radius, b.inverse_inertia},
              ContactBody{wall_velocity, wall_spin, 0.0, 0.0, 0.0});
  ++statistics_.wall_collisions[si * statistics_.wall_count + w];
  ++statistics_.wall_events;
  statistics_.wall_impulse[w] -= outcome.impulse;
  statistics_.dissipated_energy += outcome.dissipated;
  ++counter_[i];
  predict(i);
  book_collision(i, t, -1 - w);
  b.last_collision = t;
}

void Simulator::cross_cell(std::int32_t i, int face) {
  const int axis = face / 2, direction = (face % 2) ? +1 : -1;
  // Bring the stored state to the crossing: the next crossing is then predicted from "now"
  // (a particle that fell back through a face is not mistaken for one still rising), and
  // stored states never lag more than one cell behind (so one periodic image shift suffices).
  advance(i, time_);
  hot_[i].position += grid_.cross(i, axis, direction);  // a periodic wrap: one box length
  ++statistics_.cell_crossings;
  // Same trajectory: partners' predictions with i stay valid (no counter bump), and so does
  // i's own next collision; only the cells that just came into reach need a look.
  if (grid_.levels().size() > 1 || relax_)
    predict(i);
  else if (has_gravity_)
    predict_after_crossing<true>(i, axis, direction);
  else
    predict_after_crossing<false>(i, axis, direction);
}

void Simulator::book_collision(std::int32_t i, double t, std::int32_t partner_code) {
  Agenda& agenda = agenda_[i];
  if (t - agenda.stall_window_start > stall_window_) {
    agenda.stall_window_start = t;
    agenda.stall_count = 1;
    return;
  }
  if (++agenda.stall_count <= options_.collapse.stall_collisions) return;
  const ParticleStore& p = system_.particles;
  const std::string partner = partner_code >= 0
                                  ? "particle " + std::to_string(p.id[partner_code])
                                  : "wall '" + system_.walls[-1 - partner_code].name + "'";
  std::ostringstream out;
  out << "inelastic collapse at t = " << t << " s: particle " << p.id[i] << " (species "
      << system_.species[p.species[i]].name << ", at " << position(i).transpose()
      << " m) took part in " << agenda.stall_count << " collisions within "
      << (t - agenda.stall_window_start) << " s, the last with " << partner
      << ". Hard spheres cannot rest in lasting contact, so the event rate diverges. Remedy: "
         "turn on the TC model (collapse contact_time, e.g. 1e-5 s: collisions within t_c of "
         "the previous one are elastic), or make slow impacts elastic (collapse "
         "elastic_below_speed), or raise the restitution coefficient.";
  std::vector<std::uint64_t> ids{p.id[i]};
  if (partner_code >= 0) ids.push_back(p.id[partner_code]);
  throw InelasticCollapse(out.str(), ids);
}

void Simulator::check_pair_invariants(std::int32_t i, std::int32_t j, const Vec3& momentum_before) const {
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

}  // namespace carom
