// Energy bookkeeping: kinetic (translational + rotational) + potential + dissipated closes
// (EventDrivenEngine::energies().total()) in a dissipative run with gravity, rotation and walls.
#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

// 30 rough inelastic spheres (d = 1 and 0.6; e = 0.85, mu = 0.4, beta0 = 0.3 between particles;
// e = 0.75, mu = 0.5, beta0 = -0.2 on walls) in a walled 7 x 7 x 1.9 slab under g = 9.81 with
// random velocities and spins: every kind of collision, spin exchange and potential energy.
// (The slab is one grid cell high.) The TC model keeps the settling layer from collapsing.
// Reference: energy conservation, exact for the law (`dissipated` is booked per collision as
// the kinetic energy difference, potential energy is -m g.r). Tolerance 1e-11 of the initial
// total: each collision adds round-off of a few ulps of the energies involved; a random walk
// over ~1e4 collisions gives ~1e-14, while any missing term (spin energy, wall dissipation,
// potential of a delayed state) is 1e-3 or more.
TEST(EnergyBookkeeping, ClosesWithGravityRotationAndWalls) {
  test::expect_finishes(20, [] {
                System system;
                system.domain.upper = Vec3(7, 7, 1.9);
                system.species = {Species{"big", 1.0, 1000.0}, Species{"small", 0.6, 2500.0}};
                system.walls = box_walls(system.domain);
                system.materials = MaterialTable(2, system.walls.size(), ContactLaw{0.85, 0.4, 0.3},
                                                 ContactLaw{0.75, 0.5, -0.2});
                system.flight.gravity = Vec3(0, 0, -9.81);
                Rng rng(17);
                for (int k = 0; k < 30; ++k) {
                  const Vec3 r(0.6 + 1.15 * (k % 6), 0.6 + 1.15 * (k / 6), 0.55 + 0.8 * rng.uniform());
                  system.add_particle(k % 3 == 0 ? 1 : 0, r, 3.0 * rng.normal3(), 5.0 * rng.normal3());
                }
                EventDrivenOptions options;
                options.collapse.contact_time = 1e-4;
                options.check_invariants = true;
                EventDrivenEngine sim(system, options);
                const double total0 = sim.energies().total();
                const double kinetic0 = sim.energies().translational + sim.energies().rotational;
                double worst = 0;
                for (int sample = 1; sample <= 100; ++sample) {
                  sim.run_until(0.02 * sample);
                  worst = std::max(worst, std::abs(sim.energies().total() - total0) / std::abs(total0));
                }
                const Energies e = sim.energies();
                std::printf("collisions %llu, dissipated %.4g of the initial kinetic energy, worst closure %.3g\n",
                            (unsigned long long)sim.statistics().collisions(), e.dissipated / kinetic0, worst);
                EXPECT_GT(sim.statistics().pair_events, 100u);
                EXPECT_GT(sim.statistics().wall_events, 500u);
                EXPECT_GT(e.dissipated, 0.3 * kinetic0) << "the run must be strongly dissipative";
                EXPECT_LT(worst, 1e-11);
              });
}

}  // namespace
}  // namespace carom
