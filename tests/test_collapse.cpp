// Inelastic collapse: with the TC model runs finish; without it the stall detector stops the run
// with carom::InelasticCollapse naming the particle and the remedy. Nothing may hang: every run
// here is in a child process with a watchdog (test::finish_within).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
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

// The low-speed rule on both sides of the collapse (the collapse map, stability_collapse.toml): the
// same ball with impacts slower than 0.05 m/s elastic ends up bouncing elastically at about that
// speed (flights of ~2 v / g = 0.01 s, ~600 of them to t = 6 s, far below 1000 within any window)
// and finishes; the rule is what saves it, since BouncingBallWithoutTcModelThrowsDiagnostic above
// collapses at 3.635 s. With a threshold of 1e-12 m/s the bounces still shrink to flights of ~2e-13
// s, 1000 of which fit in the automatic window (1e-9 d / sqrt(g d) = 3.2e-10 s): the detector must
// fire, and its message must say that the rule is on, never advise turning it on.
TEST(Collapse, LowSpeedRuleStopsTheCollapseOnlyAboveTheBounceSpeedThatCollapses) {
  test::expect_finishes(20, [] {
    EventDrivenOptions good;
    good.collapse.elastic_below_speed = 0.05;
    EventDrivenEngine saved(bouncing_ball(), good);
    EXPECT_NO_THROW(saved.run_until(6.0));
    EXPECT_EQ(saved.time(), 6.0);
    EXPECT_LT(saved.position(0).z() - 0.5, 0.05 * 0.05 / (2 * 9.81) * 1.001)
        << "an elastic bounce at 0.05 m/s rises at most v^2 / 2g";

    EventDrivenOptions bad;
    bad.collapse.elastic_below_speed = 1e-12;
    EventDrivenEngine sim(bouncing_ball(), bad);
    try {
      sim.run_until(6.0);
      ADD_FAILURE() << "no InelasticCollapse with a threshold of 1e-12 m/s";
    } catch (const InelasticCollapse& collapse) {
      const std::string message = collapse.what();
      EXPECT_NE(message.find("slow impacts are already elastic below 1e-12 m/s"), std::string::npos)
          << message;
      EXPECT_EQ(message.find("or make slow impacts elastic"), std::string::npos) << message;
      EXPECT_NE(message.find("turn on the TC model"), std::string::npos) << message;
      EXPECT_LT(sim.time(), 3.64) << "the collapse point is t = 3.635 s";
    }
  });
}

// With the TC model on but a contact time far too short (1e-9 s) for the detector's window
// (1e-5 s, 1000 collisions), the ball's elastic rattle on the floor (period ~ t_c) is caught.
// The message must say that the TC model is on and what its setting does, never advise turning
// it on (it once did).
TEST(Collapse, DiagnosticWithTcModelOnDoesNotAdviseTurningItOn) {
  test::expect_finishes(10, [] {
    EventDrivenOptions options;
    options.collapse.contact_time = 1e-9;
    options.collapse.stall_window = 1e-5;
    EventDrivenEngine sim(bouncing_ball(), options);
    try {
      sim.run_until(6.0);
      ADD_FAILURE() << "no InelasticCollapse: the rattle was not caught";
    } catch (const InelasticCollapse& collapse) {
      const std::string message = collapse.what();
      EXPECT_EQ(message.find("turn on the TC model"), std::string::npos) << message;
      EXPECT_NE(message.find("the TC model is on (collapse contact_time = 1e-09 s)"), std::string::npos)
          << message;
      EXPECT_NE(message.find("soft_sphere"), std::string::npos) << message;
    }
  });
}

// Lasting contacts: the 27-grain column of SettlingColumnFinishesWithTcModel, at
// rest on the floor under the TC model (t_c = 1e-3 s), run on: its collision frequency per
// particle climbs as the gaps between resting grains close. The monitor measures the mean
// frequency over windows of 10 collisions per particle; the run is driven across the limit both
// ways: a limit above every window's frequency up to t_end never fires, one below the largest
// fires, with status lasting_contacts and a message naming the remedy (soft spheres).
TEST(Collapse, LastingContactsStopTheRunOnlyAboveTheLimit) {
  test::expect_finishes(60, [] {
    // First the column's own frequencies, with the monitor off.
    EventDrivenOptions options;
    options.collapse.contact_time = 1e-3;
    options.collapse.max_collision_frequency = 0.0;
    EventDrivenEngine free_run(settling_column(), options);
    double peak = 0, last_time = 0;
    std::uint64_t last_collisions = 0;
    const double t_end = 10.0;
    for (double t = 0.5; t <= t_end + 1e-9; t += 0.5) {
      free_run.run_until(t);
      const RunStatistics& s = free_run.statistics();
      const double frequency =
          (2.0 * double(s.pair_events) + double(s.wall_events) - double(last_collisions)) / (27.0 * (t - last_time));
      last_collisions = 2 * s.pair_events + s.wall_events;
      last_time = t;
      peak = std::max(peak, frequency);
      std::printf("t = %.2f s: %.4g collisions per particle per second (%.3g per t_c)\n", t, frequency,
                  frequency * 1e-3);
    }
    ASSERT_GT(peak * 1e-3, 5.0) << "the column must climb well past one collision per contact time";
    // The monitor's windows are shorter than 0.25 s, so their peak is at least the coarse one:
    // a limit at twice the coarse peak is the good side only if no short window goes above it,
    // which the run itself decides. Bad side: a third of the coarse peak must fire.
    options.collapse.max_collision_frequency = peak / 3.0;
    EventDrivenEngine bad(settling_column(), options);
    try {
      bad.run_until(t_end);
      ADD_FAILURE() << "a limit of a third of the peak frequency did not fire";
    } catch (const MethodFailure& failure) {
      EXPECT_EQ(failure.status, "lasting_contacts");
      const std::string message = failure.what();
      EXPECT_NE(message.find("soft_sphere"), std::string::npos) << message;
      EXPECT_NE(message.find("max_collision_frequency"), std::string::npos) << message;
      EXPECT_EQ(message.find("turn on the TC model"), std::string::npos) << message;
    }
    options.collapse.max_collision_frequency = 10.0 * peak;
    EventDrivenEngine good(settling_column(), options);
    EXPECT_NO_THROW(good.run_until(t_end));
    EXPECT_EQ(good.statistics().collisions(), free_run.statistics().collisions())
        << "the monitor changes nothing while it does not fire";
  });
}

// (The default limit, 50 collisions within contact_time, is on in every TC run here: the
// finishing runs above and below show that it leaves them alone.)
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
