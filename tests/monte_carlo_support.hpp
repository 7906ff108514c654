#pragma once
// Shared by the Monte Carlo tests: a closed box of two species under gravity.
#include <cstdint>

#include "core/rng.hpp"
#include "core/system.hpp"

namespace carom {

/// A closed box (walls on every axis, 0.02 x 0.02 x 0.04 m) under gravity with 400 spheres of
/// two sizes (1 in 4 large, 2 mm; the others 1 mm; glass), rough inelastic laws (e = 0.8,
/// mu = 0.3, beta0 = 0.2), random places and velocities (0.3 m/s) and spins (50 rad/s) from
/// `seed` (overlaps are allowed: the Monte Carlo method tracks no pairs).
inline System walled_box(std::uint64_t seed) {
  System system;
  system.domain.upper = Vec3(0.02, 0.02, 0.04);
  system.flight.gravity = Vec3(0, 0, -9.81);
  system.species.push_back(Species{"large", 2e-3, 2500});
  system.species.push_back(Species{"small", 1e-3, 2500});
  system.walls = box_walls(system.domain);
  ContactLaw law{0.8, 0.3, 0.2, -1.0};
  system.materials = MaterialTable(2, system.walls.size(), law, law);
  Rng rng(seed);
  for (int i = 0; i < 400; ++i) {
    const std::uint32_t s = i % 4 == 0 ? 0 : 1;
    const double a = system.species[s].radius();
    const Vec3 r(rng.uniform(a, 0.02 - a), rng.uniform(a, 0.02 - a), rng.uniform(a, 0.04 - a));
    system.add_particle(s, r, 0.3 * rng.normal3(), 50.0 * rng.normal3());
  }
  return system;
}

}  // namespace carom
