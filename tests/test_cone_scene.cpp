// Cone walls in scenes: the [[walls]] type = "cone" keys and their errors (file, line, key,
// allowed range), and a small hopper run end to end.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "tests/scene_support.hpp"
#include "test_support.hpp"

using namespace carom;
using test::error_of;
using test::expect_error;
using test::replace;

namespace {

/// A hopper: 40 glass beads of 2 mm dropped from 2..3.5 cm into a cone widening from R = 3 mm
/// at the floor (z = 0) to 11 mm at z = 4 cm (half-angle 11.3 degrees; apex at z = -1.5 cm,
/// below the box), closed by the box's floor. Line numbers: [domain] is line 1.
const std::string kHopper =
    "[domain]\n"                                            // 1
    "min = [-0.012, -0.012, 0.0]\n"                         // 2
    "max = [0.012, 0.012, 0.04]\n"                          // 3
    "gravity = [0.0, 0.0, -9.81]\n"                         // 4
    "[[species]]\n"                                         // 5
    "name = \"bead\"\n"                                     // 6
    "diameter = 2.0e-3\n"                                   // 7
    "density = 2500.0\n"                                    // 8
    "fill = { count = 40, region = \"top\" }\n"             // 9
    "[regions.top]\n"                                       // 10
    "min = [-0.005, -0.005, 0.02]\n"                        // 11
    "max = [0.005, 0.005, 0.035]\n"                         // 12
    "[[walls]]\n"                                           // 13
    "name = \"hopper\"\n"                                   // 14
    "type = \"cone\"\n"                                     // 15
    "axis = [0.0, 0.0, 0.0]\n"                              // 16
    "z_bottom = 0.0\n"                                      // 17
    "radius_bottom = 0.003\n"                               // 18
    "z_top = 0.04\n"                                        // 19
    "radius_top = 0.011\n"                                  // 20
    "[collisions]\n"                                        // 21
    "default = { e = 0.8, mu = 0.3, beta0 = 0.2 }\n"        // 22
    "walls = { e = 0.7, mu = 0.4, beta0 = 0.1 }\n"          // 23
    "collapse = { model = \"tc\", contact_time = 1e-5 }\n"  // 24
    "[time]\n"                                              // 25
    "end = 0.15\n";                                         // 26

}  // namespace

TEST(ConeScene, ReadsTheCone) {
  Scene scene = parse_scene(kHopper, "hopper.toml");
  ASSERT_EQ(scene.system.walls.size(), 7u);  // six box walls and the hopper
  const Wall& wall = scene.system.walls.back();
  EXPECT_EQ(wall.name, "hopper");
  const ConeWall& cone = std::get<ConeWall>(wall.shape);
  EXPECT_EQ(cone.radius_bottom(), 0.003);
  EXPECT_EQ(cone.radius_top(), 0.011);
  EXPECT_DOUBLE_EQ(cone.slope(), 0.2);
  EXPECT_DOUBLE_EQ(cone.apex_z(), -0.015);
  EXPECT_NE(wall.description().find("cone"), std::string::npos);
}

// Every message names the file, the line of the value, the dotted key, the value and what is
// allowed.
TEST(ConeScene, ErrorsNameFileLineKeyAndRange) {
  // The apex inside the box: R = 3 mm at z = 0.01 narrowing downwards with slope 0.4 reaches
  // zero at z = 0.0025. radius_bottom keeps it below z = 0 from 0.00375 m on: (0.00375, inf).
  const std::string apex = replace(replace(kHopper, "z_bottom = 0.0\n", "z_bottom = 0.01\n"),
                                   "radius_top = 0.011\n", "radius_top = 0.015\n");
  expect_error(apex, {"bad.toml:18", "walls[0].radius_bottom = 0.003",
                      "allowed range (0.00375, inf)", "apex at z = 0.0025 m"});
  // A duct narrowing upwards whose apex is inside the box: radius_top is named.
  const std::string duct =
      replace(replace(kHopper, "radius_bottom = 0.003\n", "radius_bottom = 0.011\n"),
              "radius_top = 0.011\n", "radius_top = 0.002\n");
  expect_error(replace(duct, "z_top = 0.04\n", "z_top = 0.02\n"),
               {"bad.toml:20", "walls[0].radius_top = 0.002", "allowed range", "apex"});
  expect_error(replace(kHopper, "z_top = 0.04\n", "z_top = -0.01\n"),
               {"bad.toml:19", "walls[0].z_top = -0.01", "allowed range (0, inf)"});
  expect_error(replace(kHopper, "radius_top = 0.011\n", "radius_top = -0.011\n"),
               {"bad.toml:20", "walls[0].radius_top = -0.011", "[0, inf)"});
  expect_error(replace(kHopper, "radius_top = 0.011\n", "radius = 0.011\n"),
               {"bad.toml", "walls[0].radius", "radius_top"});
  expect_error(replace(kHopper, "gravity = [0.0, 0.0, -9.81]\n", "gravity = [1.0, 0.0, -9.81]\n"),
               {"bad.toml:15", "walls[0].type = \"cone\"", "gravity must be along z"});
  expect_error(replace(kHopper, "gravity = [0.0, 0.0, -9.81]\n", "periodic = [\"z\"]\n"),
               {"bad.toml:15", "walls[0].type = \"cone\"", "walled z axis"});
  expect_error(replace(kHopper, "type = \"cone\"\n", "type = \"cane\"\n"),
               {"bad.toml:15", "\"cone\""});
}

// The hopper runs 0.15 s: the beads fall, hit the cone and pile up on the floor and the cone's
// wall. References: the engine's invariant checks (on: every wall collision checks the overlap,
// 1e-10 of the radius), and at 60 times the gap of every particle to every wall, which must
// not fall below -1e-10 of the radius (the engine's contact tolerance): no particle leaves the
// cone. Energy: kinetic + potential + dissipated closes to 1e-11 of the initial total, as in
// test_energy.cpp (round-off of a few ulps per collision, ~1e5 collisions; a missing term is
// 1e-3 or more). The cone must be hit (more than 100 collisions with it).
TEST(ConeScene, HopperRunKeepsParticlesInsideAndClosesTheEnergy) {
  test::expect_finishes(60, [] {
    Scene scene = parse_scene(kHopper, "hopper.toml");
    build_initial_state(scene);
    EventDrivenOptions options = scene.method.event_driven;
    options.check_invariants = true;
    EventDrivenEngine sim(scene.system, options);
    const double total0 = sim.energies().total();
    const std::size_t cone = sim.system().walls.size() - 1;
    double worst_energy = 0.0, worst_gap = 0.0;
    for (int sample = 1; sample <= 60; ++sample) {
      sim.run_until(scene.end_time * sample / 60.0);
      worst_energy =
          std::max(worst_energy, std::abs(sim.energies().total() - total0) / std::abs(total0));
      worst_gap = std::max(worst_gap, test::max_relative_wall_overlap(sim));
    }
    const std::uint64_t cone_hits = sim.statistics().wall(0, cone);
    std::printf(
        "[ hopper ] %llu collisions (%llu with the cone), worst wall overlap %.2g of a "
        "radius, worst energy closure %.2g\n",
        (unsigned long long)sim.statistics().collisions(), (unsigned long long)cone_hits, worst_gap,
        worst_energy);
    EXPECT_LE(worst_gap, 1e-10);
    EXPECT_LT(worst_energy, 1e-11);
    EXPECT_GT(cone_hits, 100u);
    // The beads came down: the mean height fell by more than a centimetre.
    double height = 0.0;
    for (std::size_t i = 0; i < sim.particle_count(); ++i) height += sim.position(i).z();
    EXPECT_LT(height / sim.particle_count(), 0.0175);
  });
}
