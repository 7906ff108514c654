// Homogeneous cooling of smooth inelastic spheres (e = 0.9) against Haff's law
// (tests/VALIDATION.md, "Homogeneous cooling"):
//   T(t) = T0 / (1 + t/t0)^2,  t0 = 6 / ((1 - e^2) omega(T0)),
// with omega the Enskog-Carnahan-Starling collision frequency: t0 = 17.8964 for m = s = T0 = 1,
// phi = 0.1.
#include <gtest/gtest.h>

#include <cmath>

#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

// Kinetic energy of the coarse-grained flow: the box cut into 2x2x2 bins, sum |P_b|^2 / (2 M_b).
// For uncorrelated thermal velocities it is (bins - 1) (3/2) T on average (the noise floor, 1.4 %
// of the thermal energy for 500 particles); a developing shear or clustering mode makes it grow.
double mean_flow_energy(const EventDrivenEngine& sim) {
  const Domain& d = sim.system().domain;
  Vec3 momentum[8];
  double mass[8] = {};
  for (auto& p : momentum) p = Vec3::Zero();
  for (std::size_t i = 0; i < sim.particle_count(); ++i) {
    Vec3 r = sim.position(i) - d.lower;
    int bin = 0;
    for (int k = 0; k < 3; ++k) {
      const double L = d.length()[k];
      const double x = r[k] - L * std::floor(r[k] / L);
      bin += (x >= 0.5 * L ? 1 : 0) << k;
    }
    momentum[bin] += sim.system().particles.mass[i] * sim.velocity(i);
    mass[bin] += sim.system().particles.mass[i];
  }
  double energy = 0;
  for (int b = 0; b < 8; ++b)
    if (mass[b] > 0) energy += 0.5 * momentum[b].squaredNorm() / mass[b];
  return energy;
}

// 500 spheres at phi = 0.1 in a periodic cube of edge 13.8 = 15 mean free paths
// (lambda = 1/(sqrt(2) pi n s^2 g0) = 0.90), well under the ~25 lambda where the homogeneous
// state of e = 0.9 becomes unstable (tests/VALIDATION.md). The gas is first equilibrated
// elastically for 10 collisions per particle (the FCC start has no pair at contact, while Haff's
// law uses the equilibrium contact value g0), then continued bit for bit with e = 0.9 through the
// restoring constructor, and T(t) is compared with Haff's law at t = t0/2, t0 and 2 t0 (T falls to
// T0/9). Tolerance 4 % on T(t)/T_Haff(t), averaged over 6 independent runs:
//  - statistics: up to 2 t0 each run has ~1.4e4 collisions; the cooled temperature is set by
//    the time integral of the cooling rate whose relative noise is ~1/sqrt(collisions) ~ 1 %
//    per run; measured scatter between seeds is 1-2 %, so ~0.7 % for the average of 6;
//  - measured: the average sits 1-3 % above Haff at 2 t0 (slower cooling as velocity
//    correlations build up, a known finite-density effect beyond Haff's law);
//  - theory: Haff's law with the Maxwellian (Enskog) rate neglects the fourth cumulant a2 of
//    the homogeneous cooling state, a2 = -0.015 at e = 0.9, which changes the cooling rate by
//    3 a2 / 16 = -0.3 %; velocity correlations and Carnahan-Starling add < 0.5 %.
// A missing factor in the dissipation (e.g. losing (1 - e) instead of (1 - e^2)) changes T(t0)
// by > 20 %.
TEST(HomogeneousCooling, HaffLawAtPhi010) {
  const double e = 0.9, t0 = 17.8964;
  const double check_times[3] = {0.5 * t0, t0, 2.0 * t0};
  double ratio_sum[3] = {0, 0, 0};
  const int runs = 6;
  for (int run = 0; run < runs; ++run) {
    GranularGasSpec spec;
    spec.count = 500;
    spec.volume_fraction = 0.1;
    spec.seed = 100 + run;
    EventDrivenOptions options;
    options.check_invariants = false;
    EventDrivenEngine elastic(make_granular_gas(spec), options);
    test::run_collisions(elastic, 10 * 500 / 2, 0.5);
    const double temperature0 = test::kinetic_temperature(elastic);
    ASSERT_NEAR(temperature0, 1.0, 1e-10);
    const double start = elastic.time();

    spec.restitution = e;
    EventDrivenEngine sim(make_granular_gas(spec), options, elastic.state());
    const double omega = test::enskog_collision_rate(500 / sim.system().domain.volume(), 1.0, 0.1, 1.0, 1.0);
    ASSERT_NEAR(6.0 / ((1 - e * e) * omega), t0, 1e-3) << "reference t0 of VALIDATION.md";
    for (int k = 0; k < 3; ++k) {
      sim.run_until(start + check_times[k]);
      const double temperature = test::kinetic_temperature(sim);
      const double haff = temperature0 / std::pow(1 + check_times[k] / t0, 2);
      ratio_sum[k] += temperature / haff;
      const double flow = mean_flow_energy(sim) / sim.energies().translational;
      std::printf("run %d t/t0 = %.1f: T = %.5f, Haff %.5f, ratio %.4f, mean-flow energy fraction %.4f\n", run,
                  check_times[k] / t0, temperature, haff, temperature / haff, flow);
      // Mean flow stays near the noise floor 7/500 = 1.4 %: 8 % allows for fluctuations (the
      // floor is a chi-square with 21 degrees of freedom: 8 % is > 4 sigma above it).
      EXPECT_LT(flow, 0.08) << "the homogeneous state is developing a mean flow (shear or clusters)";
    }
    EXPECT_GT(sim.statistics().dissipated_energy, 0.0);
  }
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(ratio_sum[k] / runs, 1.0, 0.04) << "T/T_Haff at t/t0 = " << check_times[k] / t0;
}

}  // namespace
}  // namespace carom
