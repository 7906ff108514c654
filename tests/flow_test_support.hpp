#pragma once
// Shared by the flow tests: a small system, an inflow into it, and the way a method applies a
// ParticleChange (the engines' job; here written out plainly as the tests' reference).
#include <cstring>
#include <vector>

#include "core/system.hpp"
#include "events/flow/flow_boundaries.hpp"

namespace carom::flow_test {

/// Time between flow steps in the flow tests, s.
inline constexpr double kStep = 1e-3;

/// A 2 cm x 2 cm x 10 cm box walled on every side, gravity -9.81 m/s^2 along z, one species of
/// 2 mm glass beads (2500 kg/m^3).
inline System duct() {
  System system;
  system.domain.lower = Vec3(0.0, 0.0, 0.0);
  system.domain.upper = Vec3(0.02, 0.02, 0.1);
  system.walls = box_walls(system.domain);
  system.flight.gravity = Vec3(0.0, 0.0, -9.81);
  system.species.push_back(Species{"glass", 2e-3, 2500.0});
  return system;
}

/// Beads entering downwards below the plane z = 0.09 over the whole cross-section of duct(),
/// at `per_second` particles a second, 1 m/s down.
inline Inflow top_inflow(const System& system, double per_second) {
  Inflow in;
  in.name = "top";
  in.species = 0;
  in.axis = 2;
  in.plane = 0.09;
  in.direction = -1;
  in.lower = Vec3(0.0, 0.0, 0.0);
  in.upper = Vec3(0.02, 0.02, 0.0);
  in.mass_flow = per_second * system.species[0].mass();
  in.velocity = Vec3(0.0, 0.0, -1.0);
  return in;
}

/// What a method does with a change: removes the listed particles (the others keep their
/// order) and appends the added ones.
inline void apply(const ParticleChange& change, ParticleStore& particles) {
  ParticleStore kept;
  std::size_t next_removed = 0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (next_removed < change.removed.size() && change.removed[next_removed] == i) {
      ++next_removed;
      continue;
    }
    kept.add(particles.position[i], particles.velocity[i], particles.spin[i], particles.radius[i],
             particles.mass[i], particles.inertia[i], particles.species[i], particles.id[i],
             particles.clock[i]);
  }
  const ParticleStore& a = change.added;
  for (std::size_t j = 0; j < a.size(); ++j)
    kept.add(a.position[j], a.velocity[j], a.spin[j], a.radius[j], a.mass[j], a.inertia[j],
             a.species[j], a.id[j], a.clock[j]);
  particles = std::move(kept);
}

/// Free flight without gravity or collisions for dt seconds (the tests' stand-in for a method).
inline void drift(ParticleStore& particles, double dt) {
  for (std::size_t i = 0; i < particles.size(); ++i) {
    particles.position[i] += dt * particles.velocity[i];
    particles.clock[i] += dt;
  }
}

/// True when the two stores hold the same particles bit for bit.
inline bool identical(const ParticleStore& a, const ParticleStore& b) {
  const auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() &&
           (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.position, b.position) && same(a.velocity, b.velocity) && same(a.spin, b.spin) &&
         same(a.clock, b.clock) && same(a.radius, b.radius) && same(a.mass, b.mass) &&
         same(a.inertia, b.inertia) && same(a.species, b.species) && same(a.id, b.id);
}

}  // namespace carom::flow_test
