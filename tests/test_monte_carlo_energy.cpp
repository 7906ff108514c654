// The mean energy of an elastic gas under the Monte Carlo method: partners drawn from the
// Gaussian fitted to the few particles of a collision cell heat the gas; partners drawn from the
// cell's particles themselves (monte_carlo.partner = "cell_particle") do not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "events/monte_carlo/engine.hpp"
#include "scenarios/scene/granular_gas.hpp"

namespace carom {
namespace {

struct Heating {
  double energy_ratio = 0;             ///< Kinetic energy at the end over that at the start.
  double collisions_per_particle = 0;  ///< Travelling collisions per particle.
  double bound_exceeded = 0;           ///< Thinning trials above their bound.
};

/// An elastic smooth gas of 32000 spheres (d = m = 1, T = 1, phi = 0.005, periodic box of edge
/// 149.6) in 15^3 collision cells (9.5 particles a cell on average), run for about 20
/// collisions per particle.
Heating run_elastic_gas(PartnerModel partner, std::uint64_t seed) {
  GranularGasSpec spec;
  spec.count = 32000;
  spec.volume_fraction = 0.005;
  spec.seed = seed;
  const System gas = make_granular_gas(spec);
  MonteCarloOptions options;
  options.cell_size = gas.domain.length().x() / 15.0 * (1.0 + 1e-12);
  options.partner = partner;
  options.seed = seed;
  MonteCarloEngine mc(gas, options);
  const double n = double(spec.count) / gas.domain.volume();
  const double rate = 4.0 * n * std::sqrt(std::numbers::pi);  // Boltzmann, T = 1
  const double start = mc.energies().translational;
  mc.run_until(20.0 / rate);
  Heating h;
  h.energy_ratio = mc.energies().translational / start;
  h.collisions_per_particle = double(mc.travelling_collisions()[0]) / double(spec.count);
  for (const MethodQuantity& q : mc.quantities())
    if (q.name == "thinning_bound_exceeded") h.bound_exceeded = q.value;
  return h;
}

// Elastic collisions with partners drawn from the gas's own local distribution conserve its
// mean energy: each collision gives the particle, on average, half the pair's energy difference,
// and over partners drawn with the weight |V1 - V0| from the particles themselves these cancel
// exactly. The Gaussian partner (the published model: mean and standard deviation of each
// component of the cell's other particles) has the right first two moments, but not the
// particles' distribution, and with k particles a cell the weighted exchange is biased: the gas
// heats by about 0.09/k of its energy per collision (measured with carom on dilute_gas.toml:
// ln(E_end/E_start) per collision 0.0083 +- 0.0004, 0.0049 +- 0.0005, 0.0013 +- 0.0007 at k =
// 10.6, 20.6, 49; scenarios/scenes/SCENES.md). Here, k = 9.5 and 20 collisions per particle:
// Gaussian partners heat by about 20 %; partners drawn from the cell's particles keep the energy
// within 8 %: 3 standard deviations of the random walk that remains (each collision changes the
// gas's energy at random, as the partner is fictitious). Measured over seeds 1-8 of this run:
// E_end/E_start = 0.990, sd 0.027 (cell_particle) and 1.205, sd 0.032 (gaussian); seed 3 gives
// 0.969 and 1.219. The Gaussian's run must exceed 1.1, so the bound cannot pass a heating model
// by accident (the runs differ in the partner alone). The bound of the thinning is exact for
// cell particles: never exceeded.
TEST(MonteCarloGas, CellParticlePartnersKeepAnElasticGasEnergy) {
  const Heating gaussian = run_elastic_gas(PartnerModel::Gaussian, 3);
  const Heating cell = run_elastic_gas(PartnerModel::CellParticle, 3);
  std::printf(
      "E_end/E_start after %.1f collisions per particle: gaussian %.4f, cell_particle %.4f "
      "(%.1f)\n",
      gaussian.collisions_per_particle, gaussian.energy_ratio, cell.energy_ratio,
      cell.collisions_per_particle);
  EXPECT_GT(cell.collisions_per_particle, 18.0);
  EXPECT_NEAR(cell.energy_ratio, 1.0, 0.08);
  EXPECT_EQ(cell.bound_exceeded, 0.0);
  EXPECT_GT(gaussian.energy_ratio, 1.1);
}

}  // namespace
}  // namespace carom
