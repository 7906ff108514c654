// Bidisperse elastic hard-sphere mixture: collision frequency per species pair against Enskog
// theory with the mixture contact values (tests/VALIDATION.md, "Mixtures"):
//   nu_ij = n_j pi s_ij^2 g_ij sqrt(8 T / (pi mu_ij)),  s_ij = (d_i + d_j)/2,
//   g_ij = 1/(1-phi) + 3 h xi2/(1-phi)^2 + 2 h^2 xi2^2/(1-phi)^3,  h = d_i d_j/(d_i + d_j),
//   xi2 = (pi/6) sum_k n_k d_k^2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

// 1000 particles, half of them fines with d = 0.5 (same material density, so m_fine = m/8),
// total phi = 0.25, placed by random insertion, Maxwellian at T = 1.
// Measured: nu_ij = C_ij / (N_i t) for i != j, nu_ii = 2 C_ii / (N_i t) (each like collision
// involves two particles of species i), with C from RunStatistics::pair.
// Tolerance 2.5 %:
//  - statistics: each of the three pair counts is >= 5e4 (800 collisions per particle measured) after the measuring window, so the
//    Poisson error is <= 0.4 % (1 sigma); 2.5 % is > 5 sigma of that;
//  - theory: the BMCSL mixture contact values behind g_ij are within about 1 % of simulation
//    for this size ratio and packing (Enskog theory itself is exact for the collision rate
//    given the contact value), and random sequential insertion needs ~10 collisions per
//    particle to relax to the equilibrium structure before measuring;
//  - finite size N = 1000: ~0.2 %.
// A wrong pair bookkeeping (e.g. counting each unlike collision once for both species, or using
// s_ii for s_ij) is off by 25 % or more.
TEST(BidisperseMixture, PairCollisionFrequenciesMatchEnskog) {
  GranularGasSpec spec;
  spec.count = 1000;
  spec.volume_fraction = 0.25;
  spec.fines_diameter_ratio = 0.5;
  spec.fines_number_fraction = 0.5;
  spec.seed = 5;
  EventDrivenOptions options;
  options.check_invariants = false;
  EventDrivenEngine sim(make_granular_gas(spec), options);
  const System& system = sim.system();
  ASSERT_EQ(system.species.size(), 2u);
  const double volume = system.domain.volume();
  double count[2] = {0, 0};
  for (std::uint32_t s : system.particles.species) count[s] += 1;
  const double d[2] = {system.species[0].diameter, system.species[1].diameter};
  const double m[2] = {system.species[0].mass(), system.species[1].mass()};
  const double n[2] = {count[0] / volume, count[1] / volume};
  const double phi = std::numbers::pi / 6 * (n[0] * d[0] * d[0] * d[0] + n[1] * d[1] * d[1] * d[1]);
  ASSERT_NEAR(phi, 0.25, 1e-12);

  const double slice = 0.05;
  test::run_collisions(sim, 10 * 1000 / 2, slice);  // equilibrate: ~10 collisions per particle
  const RunStatistics before = sim.statistics();
  const double t0 = sim.time();
  test::run_collisions(sim, 800 * 1000 / 2, slice);
  const double duration = sim.time() - t0;
  const RunStatistics& after = sim.statistics();

  // Temperature of each species (equipartition must hold in equilibrium).
  double kinetic[2] = {0, 0};
  for (std::size_t i = 0; i < sim.particle_count(); ++i)
    kinetic[system.particles.species[i]] += 0.5 * system.particles.mass[i] * sim.velocity(i).squaredNorm();
  const double temperature = test::kinetic_temperature(sim);
  // Per-species T has relative noise ~ sqrt(2/(3 N_s)) = 3.7 % for N_s = 500: 15 % is 4 sigma.
  for (int s = 0; s < 2; ++s) EXPECT_NEAR(2 * kinetic[s] / (3 * count[s]) / temperature, 1.0, 0.15) << "species " << s;

  const double xi2 = std::numbers::pi / 6 * (n[0] * d[0] * d[0] + n[1] * d[1] * d[1]);
  double nu[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const std::uint64_t c = after.pair(i, j) - before.pair(i, j);
      EXPECT_EQ(after.pair(i, j), after.pair(j, i)) << "pair counters must be symmetric";
      EXPECT_GT(c, 50000u);
      nu[i][j] = (i == j ? 2.0 : 1.0) * c / (count[i] * duration);
      const double sij = 0.5 * (d[i] + d[j]), h = d[i] * d[j] / (d[i] + d[j]);
      const double mu = m[i] * m[j] / (m[i] + m[j]);
      const double g = 1 / (1 - phi) + 3 * h * xi2 / std::pow(1 - phi, 2) +
                       2 * h * h * xi2 * xi2 / std::pow(1 - phi, 3);
      const double theory =
          n[j] * std::numbers::pi * sij * sij * g * std::sqrt(8 * temperature / (std::numbers::pi * mu));
      std::printf("nu_%d%d measured %.5f theory %.5f ratio %.4f (%llu collisions)\n", i, j, nu[i][j], theory,
                  nu[i][j] / theory, (unsigned long long)c);
      EXPECT_NEAR(nu[i][j] / theory, 1.0, 0.025) << "species pair " << i << j;
    }
  // Symmetry n_i nu_ij = n_j nu_ji: every unlike collision counts once for each side.
  // Exact by construction of the counters; checked to round-off.
  EXPECT_NEAR(n[0] * nu[0][1], n[1] * nu[1][0], 1e-12 * n[0] * nu[0][1]);
}

}  // namespace
}  // namespace carom
