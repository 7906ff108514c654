// The dense elastic hard-sphere fluid (phi = 0.45): no overlaps, exact conservation laws.
#include <gtest/gtest.h>

#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

// 864 smooth elastic spheres (FCC start, periodic) at phi = 0.45, where collisions are most
// frequent (omega ~ 28 per unit time) and predictions are most delicate. The engine checks its
// own invariants at every collision (check_invariants); independently, at 100 sample times an
// all-pairs O(N^2) scan of EventDrivenEngine::position(i) looks for any overlap.
// References and tolerances:
//  - overlap <= 1e-10 of the contact distance: the engine's promise (core/DESIGN.md, "Events
//    and the calendar"); a missed collision shows up as an overlap of order (relative speed x
//    sample interval), i.e. 1e-2..1e-1, ten orders above the tolerance.
//  - kinetic energy: elastic smooth collisions conserve it exactly; each collision adds
//    round-off of a few ulps of the pair's energy, a random walk over ~2.5e4 collisions gives
//    ~1e-14 of the total, so 1e-10 (the bound asked for) has four decades of margin and fails
//    on any systematic loss (e = 0.999999 would give ~1e-4).
//  - momentum: each collision is exact to round-off (1e-13 check inside the engine); total
//    drift below 1e-11 of sum m|v|.
TEST(DenseElasticGas, NoOverlapAndExactConservation) {
  GranularGasSpec spec;
  spec.count = 864;
  spec.volume_fraction = 0.45;
  spec.seed = 12;
  EventDrivenOptions options;
  options.check_invariants = true;
  EventDrivenEngine sim(make_granular_gas(spec), options);
  const std::size_t n = sim.particle_count();
  ASSERT_EQ(n, 864u);
  const double energy0 = sim.energies().translational;
  auto momentum = [&] {
    Vec3 p = Vec3::Zero();
    double scale = 0;
    for (std::size_t i = 0; i < n; ++i) {
      p += sim.system().particles.mass[i] * sim.velocity(i);
      scale += sim.system().particles.mass[i] * sim.velocity(i).norm();
    }
    return std::pair{p, scale};
  };
  const auto [momentum0, momentum_scale] = momentum();
  double worst_overlap = -1, last_time = 0;
  for (int sample = 1; sample <= 100; ++sample) {
    sim.run_until(0.02 * sample);
    ASSERT_GE(sim.time(), last_time) << "time went back";
    last_time = sim.time();
    const double overlap = test::max_relative_overlap(sim);
    worst_overlap = std::max(worst_overlap, overlap);
    ASSERT_LE(overlap, 1e-10) << "overlap at t = " << sim.time();
  }
  const double per_particle = 2.0 * sim.statistics().pair_events / double(n);
  EXPECT_GT(per_particle, 40.0) << "the run must be long enough to matter";
  const double energy = sim.energies().translational;
  EXPECT_NEAR(energy / energy0, 1.0, 1e-10);
  EXPECT_NEAR(sim.statistics().dissipated_energy / energy0, 0.0, 1e-10);
  // Smooth spheres get no tangential impulse; the torque arm n x (J_n n) is zero up to round-off.
  EXPECT_LT(sim.energies().rotational, 1e-20 * energy0) << "smooth spheres never spin up";
  EXPECT_LT((momentum().first - momentum0).norm(), 1e-11 * momentum_scale);
  std::printf("collisions per particle %.1f, worst relative overlap %.3g, energy drift %.3g\n", per_particle,
              worst_overlap, energy / energy0 - 1.0);
}

}  // namespace
}  // namespace carom
