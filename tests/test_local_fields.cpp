// Local fields on constructed particles: counts, volumes, mean flow and granular temperature
// per species and cell, and the kinetic-theory collision frequencies they imply (against
// enskog.hpp and the detailed-balance symmetry). Every random input comes from a seeded carom::Rng.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/rng.hpp"
#include "scenarios/analysis/enskog.hpp"
#include "scenarios/analysis/local_fields.hpp"
#include "analysis_support.hpp"
#include "scenarios/analysis/sample_grid.hpp"

namespace carom {
namespace {

using test::unit_cube_grid;

// ---------------------------------------------------------------------------------------------
// Local fields

/// Appends `pairs` pairs of particles of `species` at random points of the box [lower, upper]
/// with velocities mean +- amplitude e (e a random unit vector per pair): their mean is `mean`
/// and each |v - mean|^2 = amplitude^2, so theta = amplitude^2/3 exactly.
struct Particles {
  std::vector<Vec3> position, velocity;
  std::vector<std::uint32_t> species;
  std::vector<double> radius;
};
void add_pairs(Particles& p, int pairs, std::uint32_t species, double radius, const Vec3& lower,
               const Vec3& upper, const Vec3& mean, double amplitude, Rng& rng) {
  for (int k = 0; k < pairs; ++k) {
    const Vec3 direction = rng.normal3().normalized();
    for (double sign : {1.0, -1.0}) {
      const Vec3 u(rng.uniform(), rng.uniform(), rng.uniform());
      p.position.push_back(lower + u.cwiseProduct(upper - lower));
      p.velocity.push_back(mean + sign * amplitude * direction);
      p.species.push_back(species);
      p.radius.push_back(radius);
    }
  }
}

// Two cells, each species with its own mean flow and fluctuation amplitude: counts and volumes
// exact, mean velocities and temperatures to round-off (1e-13 relative).
TEST(LocalFields, TemperatureAboutLocalMeanFlow) {
  Rng rng(41);
  Particles p;
  const Vec3 left_lo(0, 0, 0), left_hi(1, 1, 1), right_lo(1, 0, 0), right_hi(2, 1, 1);
  add_pairs(p, 3, 0, 0.01, left_lo, left_hi, Vec3(1.0, -2.0, 0.5), 0.3, rng);
  add_pairs(p, 2, 1, 0.005, left_lo, left_hi, Vec3(0.0, 0.0, -4.0), 0.1, rng);
  add_pairs(p, 1, 0, 0.01, right_lo, right_hi, Vec3(7.0, 0.0, 0.0), 0.6, rng);
  p.position.push_back(Vec3(1.5, 0.5, 0.5)), p.velocity.push_back(Vec3(1, 2, 3));
  p.species.push_back(1), p.radius.push_back(0.005);  // a lone fine: theta 0, skipped in the mean
  SampleGrid grid;
  grid.upper = Vec3(2, 1, 1);
  grid.cells = {2, 1, 1};
  const LocalFields f =
      local_fields(p.position, p.velocity, p.species, p.radius, 2, grid, {1.0, 0.5});
  EXPECT_EQ(f.count[f.at(0, 0)], 6u);
  EXPECT_EQ(f.count[f.at(0, 1)], 4u);
  EXPECT_EQ(f.count[f.at(1, 0)], 2u);
  EXPECT_EQ(f.count[f.at(1, 1)], 1u);
  const double sphere = 4.0 / 3.0 * std::numbers::pi;
  EXPECT_NEAR(f.solid_volume[f.at(0, 0)], 6 * sphere * 1e-6, 1e-20);
  EXPECT_NEAR(f.number_density(1, 0), 2.0 / 0.5, 1e-15) << "open volume, not the cell volume";
  EXPECT_NEAR((f.mean_velocity[f.at(0, 0)] - Vec3(1.0, -2.0, 0.5)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((f.mean_velocity[f.at(1, 0)] - Vec3(7.0, 0.0, 0.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(f.granular_temperature[f.at(0, 0)] / (0.09 / 3.0), 1.0, 1e-13);
  EXPECT_NEAR(f.granular_temperature[f.at(0, 1)] / (0.01 / 3.0), 1.0, 1e-13);
  EXPECT_NEAR(f.granular_temperature[f.at(1, 0)] / (0.36 / 3.0), 1.0, 1e-13);
  EXPECT_EQ(f.granular_temperature[f.at(1, 1)], 0.0);
  const std::vector<double> theta = species_granular_temperature(f);
  EXPECT_NEAR(theta[0] / ((6 * 0.09 + 2 * 0.36) / 3.0 / 8.0), 1.0, 1e-13);
  EXPECT_NEAR(theta[1] / (0.01 / 3.0), 1.0, 1e-13);
  EXPECT_THROW(local_fields(p.position, p.velocity, p.species, p.radius, 1, grid),
               std::invalid_argument);
}

// One uniform cell of a binary mixture at equal temperatures T = m_s theta_s: the local-field
// frequencies must be enskog.hpp's enskog_frequency (same formula, evaluated differently: the
// fields give theta_s + theta_t = T/mu_st), to round-off, 1e-12 relative.
TEST(LocalFields, OneCellReproducesEnskogFrequencies) {
  Rng rng(42);
  const double T = 0.7, d0 = 0.1, d1 = 0.05, m0 = 1.0, m1 = 0.125;
  Particles p;
  add_pairs(p, 100, 0, 0.5 * d0, Vec3::Zero(), Vec3::Ones(), Vec3(0.2, 0, 0), std::sqrt(3 * T / m0),
            rng);
  add_pairs(p, 150, 1, 0.5 * d1, Vec3::Zero(), Vec3::Ones(), Vec3(0, 0, -1), std::sqrt(3 * T / m1),
            rng);
  const LocalFields f =
      local_fields(p.position, p.velocity, p.species, p.radius, 2, unit_cube_grid(1, 1, 1));
  const std::vector<double> nu = kinetic_collision_frequencies(f);
  const std::vector<MixtureComponent> mixture = {{200.0, d0, m0}, {300.0, d1, m1}};
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t t = 0; t < 2; ++t)
      EXPECT_NEAR(nu[2 * s + t] / enskog_frequency(mixture, s, t, T), 1.0, 1e-12) << s << "-" << t;
}

// Three species in 27 cells at random, some with a lone particle of a species (fallback
// temperature): n_s nu_st = n_t nu_ts in every cell and N_s nu_st = N_t nu_ts for the bed
// averages, to round-off (1e-12 relative), because g_st = g_ts and theta_s + theta_t is symmetric.
TEST(LocalFields, CollisionFrequencySymmetry) {
  Rng rng(43);
  Particles p;
  const double radii[3] = {0.02, 0.01, 0.005};
  const int pairs[3] = {30, 40, 80};
  for (std::uint32_t s = 0; s < 3; ++s)
    add_pairs(p, pairs[s], s, radii[s], Vec3::Zero(), Vec3::Ones(), rng.normal3(), 0.5 + 0.3 * s,
              rng);
  const LocalFields f =
      local_fields(p.position, p.velocity, p.species, p.radius, 3, unit_cube_grid(3, 3, 3));
  const std::vector<double> fallback = species_granular_temperature(f);
  int lone = 0;
  for (std::size_t cell = 0; cell < 27; ++cell) {
    const std::vector<double> nu = cell_collision_frequencies(f, cell, fallback);
    for (std::size_t s = 0; s < 3; ++s) {
      lone += f.count[f.at(cell, s)] == 1;
      for (std::size_t t = 0; t < 3; ++t) {
        const double forward = f.number_density(cell, s) * nu[3 * s + t];
        const double backward = f.number_density(cell, t) * nu[3 * t + s];
        EXPECT_NEAR(forward, backward, 1e-12 * std::max(1.0, std::abs(forward)));
      }
    }
  }
  EXPECT_GT(lone, 0) << "the test is meant to exercise the fallback temperature";
  const std::vector<double> nu = kinetic_collision_frequencies(f);
  for (std::size_t s = 0; s < 3; ++s)
    for (std::size_t t = 0; t < 3; ++t) {
      const double forward = 2.0 * pairs[s] * nu[3 * s + t],
                   backward = 2.0 * pairs[t] * nu[3 * t + s];
      EXPECT_NEAR(forward / backward, 1.0, 1e-12);
    }
}

}  // namespace
}  // namespace carom
