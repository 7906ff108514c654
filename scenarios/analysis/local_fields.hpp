#pragma once
/// Local fields of a granular mixture on sample cells, per species: particle count, solid volume,
/// mean velocity and granular temperature; the species' bed-averaged temperatures; and the
/// kinetic-theory (Enskog) collision frequencies those fields imply, for comparison with the
/// collision counts a run measures. Pure functions on plain data (SI units).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "scenarios/analysis/sample_grid.hpp"

namespace carom {

/// Per-cell, per-species fields; per-(cell, species) arrays are indexed at(cell, species).
///
/// Centre binning: a particle counts wholly in the cell holding its centre, so the solid volume
/// of a cell is the sum of the sphere volumes of the particles centred in it. That misplaces
/// volume across cell faces by up to a particle radius, a relative error of order d/L in a cell
/// of edge L: cells should span several large diameters.
struct LocalFields {
  SampleGrid grid;                  ///< The sample cells.
  std::size_t species_count = 0;    ///< S: species ids run from 0 to S - 1.
  std::vector<double> open_volume;  ///< Volume open to particles in each cell, m^3.
  /// Mean diameter of each species' particles (all of them, in the grid or not), m; 0 if none.
  std::vector<double> species_diameter;
  std::vector<std::size_t> count;    ///< Particles of the species centred in the cell.
  std::vector<double> solid_volume;  ///< Sum of their sphere volumes, m^3.
  std::vector<Vec3> mean_velocity;   ///< u: their mean velocity, m/s; NaN with no particle.
  /// theta = <|v - u|^2>/3 over the species' particles in the cell, m^2/s^2 (fluctuations about
  /// the local mean flow of that species; 1/N average, so 0 for one particle and low by the
  /// factor (N - 1)/N for N thermal particles); NaN with no particle.
  std::vector<double> granular_temperature;

  /// Flat index of (cell, species) in the per-(cell, species) arrays.
  std::size_t at(std::size_t cell, std::size_t species) const {
    return cell * species_count + species;
  }
  /// Number density of the species in the cell, 1/m^3; NaN where the open volume is not positive.
  double number_density(std::size_t cell, std::size_t species) const;
  /// Solid volume fraction of all species in the cell; NaN where the open volume is not positive.
  double solid_fraction(std::size_t cell) const;
};

/// Bins the particles (positions m, velocities m/s, species ids < species_count, radii m) into
/// the cells of `grid`; particles outside the grid are ignored. open_volume (m^3, one per cell)
/// is the volume open to particles, for cells cut by walls or obstacles; empty means the
/// geometric cell volume everywhere.
/// Throws std::invalid_argument for inputs of different lengths, a species id >= species_count,
/// an open_volume of the wrong length or an invalid grid.
LocalFields local_fields(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                         const std::vector<std::uint32_t>& species,
                         const std::vector<double>& radii, std::size_t species_count,
                         const SampleGrid& grid, const std::vector<double>& open_volume = {});

/// Bed-averaged granular temperature of each species, m^2/s^2: the cells' theta averaged with
/// the species' count in each cell as weight, over the cells holding at least 2 of its particles
/// (one particle has no fluctuation to measure). NaN for a species with no such cell.
std::vector<double> species_granular_temperature(const LocalFields& fields);

/// Kinetic-theory collision frequencies in one cell, an S x S row-major matrix, 1/s: entry
/// (s, t) is the rate at which one particle of species s meets particles of species t,
///   nu_st = n_t pi d_st^2 g_st sqrt(8 (theta_s + theta_t)/pi),   d_st = (d_s + d_t)/2.
/// This is tests/VALIDATION.md's ("Mixtures") nu_ij = n_j pi s_ij^2 g_ij sqrt(8 T/(pi mu_ij)) for
/// species at their own temperatures T_s = m_s theta_s: the mean relative speed of two Maxwellians
/// with velocity variances theta_s and theta_t per component is sqrt(8 (theta_s + theta_t)/pi), and
/// for equal T, theta_s + theta_t = T/m_s + T/m_t = T/mu_st. n from the cell's counts and open
/// volume, d_s the species' mean diameter, g_st the BMCSL contact value of enskog.hpp at the cell's
/// number densities. n_s nu_st = n_t nu_ts holds by construction (g_st = g_ts). A species with
/// fewer than 2 particles in the cell takes its temperature from fallback_temperature (m^2/s^2,
/// e.g. species_granular_temperature; 0 where that is NaN). The whole matrix is NaN where the open
/// volume is not positive or the centre-binned solid fraction reaches 1 (cells too small for centre
/// binning). With impact_speed v* > 0, only the impacts: the collisions whose normal approach
/// speed exceeds v* (scenarios/scene/impact_speed.hpp), nu_st times impact_share.
std::vector<double> cell_collision_frequencies(const LocalFields& fields, std::size_t cell,
                                               const std::vector<double>& fallback_temperature,
                                               double impact_speed = 0.0);

/// The share of the collisions of two Maxwellian species whose normal approach speed w exceeds
/// v* = impact_speed: exp(-v*^2 / (2 sigma^2)), sigma^2 = theta_s + theta_t the variance of the
/// relative velocity per component (relative_variance, m^2/s^2). Collisions happen at the rate
/// w f(w) over approaching w > 0, f Gaussian of variance sigma^2, and
///   int_v*^inf w exp(-w^2/(2 sigma^2)) dw / int_0^inf (the same) = exp(-v*^2/(2 sigma^2)).
/// 1 when v* = 0; 0 when v* > 0 and sigma^2 = 0.
double impact_share(double impact_speed, double relative_variance);

/// Bed-averaged kinetic-theory collision frequencies, S x S row-major, 1/s: each cell's
/// cell_collision_frequencies (fallback: species_granular_temperature) averaged over the cells
/// with the count of species s as weight for row s; cells where the matrix is NaN are skipped.
/// With N_s the count of s in the cells used, N_s nu_st = N_t nu_ts holds as it does per cell.
/// NaN in a row whose species is in no usable cell. With impact_speed > 0: the impacts only (see
/// cell_collision_frequencies).
std::vector<double> kinetic_collision_frequencies(const LocalFields& fields,
                                                  double impact_speed = 0.0);

}  // namespace carom
