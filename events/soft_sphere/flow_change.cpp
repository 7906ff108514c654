// Particles leaving and entering the soft-sphere method (inflow, outflow), between two steps.
#include <vector>

#include "events/particle_change.hpp"
#include "events/soft_sphere/engine.hpp"

namespace carom {

void SoftSphereEngine::apply_change(const ParticleChange& change) {
  check_particle_change(change, system_, time_);
  ParticleStore& p = system_.particles;
  flow_energy_ += change_energy(change, p, system_.flight.gravity);

  // New index of each old particle (-1: it leaves).
  std::vector<std::int32_t> new_index(p.size(), -1);
  for (std::size_t i = 0, next = 0, kept = 0; i < p.size(); ++i) {
    if (next < change.removed.size() && change.removed[next] == i) {
      ++next;
      continue;
    }
    new_index[i] = static_cast<std::int32_t>(kept++);
  }
  // The contact histories of the pairs that stay: the order of the remaining particles is kept,
  // so the owner rule (the lower index among equal sizes) and the lists' order still hold.
  std::vector<PairContactState> pairs;
  for (PairContactState c : list_.pairs()) {
    c.owner = new_index[c.owner];
    c.partner = new_index[c.partner];
    if (c.owner >= 0 && c.partner >= 0) pairs.push_back(c);
  }
  std::vector<WallContactState> walls;
  for (WallContactState c : list_.wall_pairs()) {
    c.particle = new_index[c.particle];
    if (c.particle >= 0) walls.push_back(c);
  }
  list_.restore({}, std::move(pairs), std::move(walls));

  follow_change(flights_, change, RelaxFlight{0.0, system_.flight.gravity});
  follow_change(inverse_mass_, change, 0.0);
  follow_change(inverse_inertia_, change, 0.0);
  const std::size_t first_new = p.size() - change.removed.size();
  apply_particle_change(change, p, statistics_.tagged);
  for (std::size_t i = first_new; i < p.size(); ++i) {
    inverse_mass_[i] = 1.0 / p.mass[i];
    inverse_inertia_[i] = 1.0 / p.inertia[i];
  }
  force_.assign(p.size(), Vec3::Zero());
  torque_.assign(p.size(), Vec3::Zero());

  // Forces at the present positions, for the next step's first half kick. The contacts of the
  // particles that left took their spring energy with them: it is booked as carried out.
  const double elastic_before = elastic_;
  list_.build(p.position, p.radius, system_.walls);
  travelled_ = 0.0;
  compute_forces(0.0, true);
  flow_energy_ -= elastic_before - elastic_;
}

}  // namespace carom
