// Inelastic collapse: with the TC model runs finish; without it the stall detector stops the run
// with carom::InelasticCollapse naming the particle and the remedy. Nothing may hang: every run
// here is in a child process with a watchdog (test::finish_within).
#include <gtest/gtest.h>

#include <string>

#include "core/rng.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

// A ball (d = 1) dropped from rest 0.8 above a floor with e = 0.8 under g = 9.81. Bounce times
// shrink geometrically (t_k ~ 0.8^k), so infinitely many bounces happen before t = 3.635 s
// (fall 0.404 s, then flights 0.646 (1 + 0.8 + 0.8^2 + ...) = 3.231 s): the
// textbook inelastic collapse. The box is 1.9 high, so z has a single grid cell.
System bouncing_ball() {
  System system;
  system.domain.upper = Vec3(3, 3, 1.9);
  system.species.push_back(Species{"ball", 1.0, 1000.0});
  system.walls = box_walls(system.domain);
  system.materials = MaterialTable(1, system.walls.size(), ContactLaw{0.8, 0, 0}, ContactLaw{0.8, 0, 0});
  system.flight.gravity = Vec3(0, 0, -9.81);
  system.add_particle(0, Vec3(1.5, 1.5, 1.3), Vec3::Zero());
  return system;
}

// 27 spheres (d = 1, e = 0.7, mu = 0.3) on a 3x3x3 lattice with random velocities, settling in a
// walled 4.2 x 4.2 x 8 box under gravity: they come to rest on the floor and on each other.
System settling_column() {
  System system;
  system.domain.upper = Vec3(4.2, 4.2, 8.0);
  system.species.push_back(Species{"grain", 1.0, 1000.0});
  system.walls = box_walls(system.domain);
  const ContactLaw law{0.7, 0.3, 0.0};
  system.materials = MaterialTable(1, system.walls.size(), law, law);
  system.flight.gravity = Vec3(0, 0, -9.81);
  Rng rng(3);
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z)
        system.add_particle(0, Vec3(0.8 + 1.3 * x, 0.8 + 1.3 * y, 1.0 + 2.0 * z), rng.normal3());
  return system;
}

// With the TC model (contact_time 1e-3 s: a collision within t_c of the previous one is elastic)
// the ball ends up bouncing elastically with a flight time ~ t_c, so run_until(6 s) finishes
// (~3e3 events); it must be resting on the floor within 1e-3 of its radius... of the floor
// (its height above the floor at most g t_c^2 / 8 ~ 1e-6 m plus the last real bounce).
TEST(Collapse, BouncingBallFinishesWithTcModel) {
  test::expect_finishes(10, [] {
                EventDrivenOptions options;
                options.collapse.contact_time = 1e-3;
                EventDrivenEngine sim(bouncing_ball(), options);
                EXPECT_NO_THROW(sim.run_until(6.0));
                EXPECT_EQ(sim.time(), 6.0);
                EXPECT_LT(sim.position(0).z() - 0.5, 1e-3) << "the ball must have come to (practical) rest";
                EXPECT_LT(test::max_relative_wall_overlap(sim), 1e-10);
              });
}

// A ball at rest exactly touching the ceiling must simply fall away under gravity: the gap
// grows as g s^2 / 2, so there is no contact to process. Reference: free fall; it reaches the
// floor at t = sqrt(2 * 0.9 / 9.81) = 0.4284 s. Before that there must be no wall collision at
// all (a repeated zero-time "collision" with the ceiling is a bug, and the stall detector would
// then misreport it as inelastic collapse).
TEST(Collapse, BallTouchingTheCeilingFallsAway) {
  test::expect_finishes(5, [] {
    System system = bouncing_ball();
    system.particles.position[0].z() = 1.4;  // centre at 1.9 - 0.5: touching z_high
    EventDrivenEngine sim(system, EventDrivenOptions{});
    EXPECT_NO_THROW(sim.run_until(0.42));
    EXPECT_EQ(sim.statistics().wall_events, 0u) << "no contact while falling away from the ceiling";
    EXPECT_NEAR(sim.position(0).z(), 1.4 - 0.5 * 9.81 * 0.42 * 0.42, 1e-12);
  });
}

// Without it the stall detector must throw, naming the particle (id 0) and the TC model.
TEST(Collapse, BouncingBallWithoutTcModelThrowsDiagnostic) {
  test::expect_finishes(10, [] {
                EventDrivenEngine sim(bouncing_ball(), EventDrivenOptions{});
                try {
                  sim.run_until(6.0);
                  ADD_FAILURE() << "no InelasticCollapse: the run went through the collapse";
                } catch (const InelasticCollapse& collapse) {
                  const std::string message = collapse.what();
                  EXPECT_NE(message.find("particle 0"), std::string::npos) << message;
                  EXPECT_NE(message.find("TC model"), std::string::npos) << message;
                  ASSERT_FALSE(collapse.particle_ids.empty());
                  EXPECT_EQ(collapse.particle_ids[0], 0u);
                  EXPECT_LT(sim.time(), 3.64) << "the collapse point is t = 3.635 s";
                }
              });
}

TEST(Collapse, SettlingColumnFinishesWithTcModel) {
  test::expect_finishes(20, [] {
                EventDrivenOptions options;
                options.collapse.contact_time = 1e-3;
                options.check_invariants = true;
                EventDrivenEngine sim(settling_column(), options);
                EXPECT_NO_THROW(sim.run_until(2.0));
                EXPECT_EQ(sim.time(), 2.0);
                EXPECT_LT(test::max_relative_overlap(sim), 1e-10);
                EXPECT_LT(test::max_relative_wall_overlap(sim), 1e-10);
              });
}

TEST(Collapse, SettlingColumnWithoutTcModelThrowsDiagnostic) {
  test::expect_finishes(20, [] {
                EventDrivenEngine sim(settling_column(), EventDrivenOptions{});
                try {
                  sim.run_until(5.0);
                  ADD_FAILURE() << "no InelasticCollapse in a settling column without the TC model";
                } catch (const InelasticCollapse& collapse) {
                  const std::string message = collapse.what();
                  EXPECT_NE(message.find("particle "), std::string::npos) << message;
                  EXPECT_NE(message.find("TC model"), std::string::npos) << message;
                  EXPECT_FALSE(collapse.particle_ids.empty());
                }
              });
}

}  // namespace
}  // namespace carom
