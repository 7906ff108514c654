#include "events/particle_change.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace carom {

void check_particle_change(const ParticleChange& change, const System& system, double time) {
  const std::size_t n = system.particles.size();
  for (std::size_t k = 0; k < change.removed.size(); ++k) {
    if (change.removed[k] >= n)
      throw std::logic_error("particle change: removed index " + std::to_string(change.removed[k]) +
                             " is beyond the " + std::to_string(n) + " particles");
    if (k > 0 && change.removed[k] <= change.removed[k - 1])
      throw std::logic_error("particle change: removed indices must be ascending and distinct");
  }
  const ParticleStore& a = change.added;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.species[i] >= system.species.size() || system.species[a.species[i]].fixed)
      throw std::logic_error(
          "particle change: an entering particle of an unknown or fixed species");
    if (!a.position[i].allFinite() || !a.velocity[i].allFinite() || !a.spin[i].allFinite() ||
        !(a.radius[i] > 0.0) || !(a.mass[i] > 0.0) || !(a.inertia[i] > 0.0))
      throw std::logic_error("particle change: an entering particle with a non-finite state");
    if (a.clock[i] != time)
      throw std::logic_error(
          "particle change: an entering particle's clock is not the step's time");
  }
}

double change_energy(const ParticleChange& change, const ParticleStore& p, const Vec3& gravity) {
  double energy = 0.0;
  for (std::size_t i = 0; i < change.added.size(); ++i)
    energy += carried_energy(change.added, i, gravity);
  for (std::size_t i : change.removed) energy -= carried_energy(p, i, gravity);
  return energy;
}

void apply_particle_change(const ParticleChange& change, ParticleStore& particles,
                           TaggedImpulses& tagged) {
  particles.erase(change.removed);
  particles.append(change.added);
  if (!tagged.any()) return;
  std::unordered_map<std::uint64_t, std::int32_t> slot_by_id;
  for (std::size_t k = 0; k < tagged.ids.size(); ++k)
    slot_by_id.emplace(tagged.ids[k], static_cast<std::int32_t>(k));
  tagged.slot_of.assign(particles.size(), -1);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const auto it = slot_by_id.find(particles.id[i]);
    if (it != slot_by_id.end()) tagged.slot_of[i] = it->second;
  }
}

}  // namespace carom
