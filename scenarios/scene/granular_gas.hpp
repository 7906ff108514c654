#pragma once
/// Builders for periodic granular gases: the hard-sphere fluid of the benchmarks and tests.
#include <cstdint>

#include "core/system.hpp"

namespace carom {

/// A periodic cube of hard spheres (one or two species) with Maxwellian velocities.
struct GranularGasSpec {
  std::size_t count = 1000;        ///< Total number of particles (monodisperse: rounded to 4 k^3).
  double volume_fraction = 0.3;    ///< phi, total solid volume / box volume.
  double diameter = 1.0;           ///< Large (or only) diameter, m.
  double density = 6.0 / 3.14159265358979323846;  ///< kg/m^3; the default gives m = 1 for d = 1.
  double fines_diameter_ratio = 1.0;  ///< d_fine / d_large; 1 means monodisperse.
  double fines_number_fraction = 0.0; ///< Fraction of the particles that are fines.
  double temperature = 1.0;        ///< Granular temperature T = m <v_x^2>, J (per particle).
  double restitution = 1.0;        ///< e for every pair (smooth spheres, mu = 0).
  std::uint64_t seed = 1;          ///< Random seed for placement and velocities.
};

/// Monodisperse gases start on an FCC lattice (any phi up to 0.74); mixtures are placed by
/// random sequential insertion, large first (phi up to about 0.35). Total momentum is zero and
/// the kinetic temperature is exactly `temperature`.
System make_granular_gas(const GranularGasSpec& spec);

}  // namespace carom
