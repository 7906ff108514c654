#pragma once
/// Mixing of two populations of particles: the Lacey index of a tagged population over sample
/// cells, the rate at which it approaches 1, and height-based segregation indices of two species.
/// Pure functions on plain data (positions in m, times in s); the run loop calls them at each
/// sample time.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "scenarios/analysis/sample_grid.hpp"

namespace carom {

/// The Lacey mixing index of a tagged population and the numbers it is made of.
struct LaceyIndex {
  /// M = (s0^2 - s^2)/(s0^2 - sr^2): 0 segregated, 1 random; NaN if undefined.
  double index;
  /// s^2: content-weighted variance of the tagged fraction over the cells used.
  double variance;
  double segregated_variance;  ///< s0^2 = P (1 - P), the variance of a fully segregated state.
  double random_variance;      ///< sr^2 = P (1 - P)/n, the expected variance of a random mixture.
  double tagged_fraction;      ///< P: tagged particles / particles, over the cells used.
  double particles_per_cell;   ///< n = (N - 1)/(K - 1), particles per sample (see lacey_index).
  std::size_t cells_used;      ///< K: cells holding at least min_particles_per_cell particles.
};

/// Lacey index of the particles at `positions` (only those given: pass e.g. the large ones),
/// tagged[i] != 0 marking the tagged population, over the cells of `grid`.
///
/// Cells holding fewer than `min_particles_per_cell` of the given particles are skipped (their
/// tagged fraction is mostly counting noise), as are particles outside the grid. Over the K cells
/// left, holding N particles of which T are tagged (P = T/N), with N_k and x_k the count and
/// tagged fraction of cell k:
///   s^2 = sum_k N_k (x_k - P)^2 / N,   s0^2 = P (1 - P),   sr^2 = P (1 - P)/n,
///   n = (N - 1)/(K - 1).
/// Why this n: for a random mixture (the tags a random permutation over the particles, i.e.
/// drawn independently and then conditioned on their total T), the cell counts T_k are
/// multivariate hypergeometric and E[sum_k T_k^2/N_k] = P(1-P) N (K-1)/(N-1) + N P^2, so
/// E[s^2 | T] = P (1 - P) (K - 1)/(N - 1) exactly. Since M = (1 - s^2/s0^2)/(1 - 1/n) is linear in
/// s^2 given T, this n makes E[M] = 1 exactly for every T, every cell occupancy and every K >= 2.
/// (It is the mean count N/K up to O(1/K); the content weighting is what makes the arithmetic,
/// not the harmonic, mean the right one.) A fully segregated state (every used cell all tagged or
/// all untagged) has s^2 = s0^2 and M = 0 exactly.
/// Degenerate cases give index NaN (the other fields filled as far as defined): no particle
/// tagged or all tagged among the used cells (P = 0 or 1: nothing to mix), or fewer than two
/// usable cells (no variance between cells).
/// Throws std::invalid_argument if positions and tagged differ in length or the grid is invalid.
LaceyIndex lacey_index(const std::vector<Vec3>& positions, const std::vector<char>& tagged,
                       const SampleGrid& grid, std::size_t min_particles_per_cell = 5);

/// Least-squares fit of a mixing curve M(t) = 1 - exp(-k t).
struct MixingRate {
  double rate;  ///< k, 1/s; 0 or +inf when the data pin it at the end of the search range.
  double time_to_08_fit;  ///< ln((1 - M0)/0.2)/k: when the fitted curve reaches M = 0.8, s.
  double
      time_to_08_data;  ///< First time the data reach 0.8 (linear interpolation), s; NaN if never.
  double rms_residual;  ///< sqrt(mean (M_i - fit_i)^2) over the points used.
  std::size_t points;   ///< Points used (finite time >= 0 and finite M).
  bool valid;           ///< At least 3 points and k determined inside the search range.
  double start;         ///< M0, the start of the fitted curve (the measured M(0), or 0).
};

/// Fits M(t) = 1 - (1 - M0) exp(-k t) to Lacey indices `lacey` at `times` (s, measured from the
/// tagging instant) by least squares in M, with M0 = `start` fixed: the measured M(0) (sample
/// cells that do not split the bed exactly at the tagging height give M(0) > 0; forcing the
/// curve through 0 would bend k to fit a start the data do not have), or 0 for the classic
/// 1 - exp(-k t). Points with a non-finite value or a negative time are skipped; values above
/// 1 (noise about a mixed state) are kept as they are. A start of 0.8 or more leaves nothing
/// to fit (rate NaN, valid false).
///
/// The solver cannot diverge: the sum of squares is scanned over a logarithmic grid of k from
/// 1e-4/t_max (mixing invisible within the data) to 1e3/t_min (mixed before the first positive
/// sample), 40 points per decade, and the best grid point is refined by bisection in ln k on the
/// normal equation sum_i r_i t_i exp(-k t_i) = 0 (r_i the residuals) between its neighbours,
/// which brackets it; that converges to round-off. When the best grid point is an end of the
/// range, k is reported as 0 (no mixing seen: time_to_08_fit = +inf) or +inf (mixed before the
/// first sample: time_to_08_fit = 0) and valid is false. With fewer than 3 points, or no
/// positive time, rate and time_to_08_fit are NaN and valid is false; time_to_08_data is computed
/// from whatever points there are (taken in time order).
/// Throws std::invalid_argument if times and lacey differ in length.
MixingRate fit_mixing_rate(const std::vector<double>& times, const std::vector<double>& lacey,
                           double start = 0.0);

/// Height segregation index of species a against species b:
///   S = 2 (h_a - h_b)/(h_a + h_b),
/// h_s the mean height of the centres of species s above floor_height (m) along vertical_axis.
/// S = 0 for species at the same mean height (well mixed, or segregated symmetrically), S > 0
/// with a above b (e.g. flotsam a on top), |S| up to 2. Only particles of species a and b count.
/// NaN if either species is absent or h_a + h_b = 0.
/// Throws std::invalid_argument if positions and species differ in length or the axis is not 0-2.
double segregation_index(const std::vector<Vec3>& positions,
                         const std::vector<std::uint32_t>& species, std::uint32_t a,
                         std::uint32_t b, double floor_height, int vertical_axis = 2);

/// The Rowe-Nienow mixing index of fluidized beds (Rowe, Nienow and Agbim 1972, Trans. Inst.
/// Chem. Eng. 50, 310), the established binary index there:
///   M_RN = x_upper / x_mean,
/// x the volume fraction of the jetsam (the species that sinks) among the solids of species
/// `jetsam` and `flotsam`, x_upper over the particles whose centre lies above split_height (m,
/// along vertical_axis; usually the bed's mid-height by solids volume) and x_mean over all of
/// them. Volumes are the sphere volumes of `radii` (m), i.e. mass fractions for equal densities.
/// M_RN = 1 well mixed, 0 with no jetsam in the upper part (fully segregated). NaN if there is
/// no jetsam, or no particle of the two species above split_height.
/// Throws std::invalid_argument if the vectors differ in length or the axis is not 0-2.
double rowe_nienow_index(const std::vector<Vec3>& positions,
                         const std::vector<std::uint32_t>& species,
                         const std::vector<double>& radii, std::uint32_t jetsam,
                         std::uint32_t flotsam, double split_height, int vertical_axis = 2);

}  // namespace carom
