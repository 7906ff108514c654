// The [[inflow]], [[outflow]] and [flow] scene keys (scenarios/scene/flow_scene.hpp): what they
// read, their defaults, and every class of mistake refused with the file, line, key and
// allowed range (SCENES.md, "Inflow and outflow").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "tests/scene_support.hpp"

using namespace carom;
using test::expect_parse_error;
using test::replace;

namespace {

/// A vertical duct 2 cm x 1 cm x 10 cm, periodic on y, with an inlet at the top and an outlet
/// at the bottom. Line numbers: [domain] is line 1.
const std::string kDuct =
    "[domain]\n"                           // 1
    "min = [0.0, 0.0, 0.0]\n"              // 2
    "max = [0.02, 0.01, 0.1]\n"            // 3
    "periodic = [\"y\"]\n"                 // 4
    "gravity = [0.0, 0.0, -9.81]\n"        // 5
    "[[species]]\n"                        // 6
    "name = \"bead\"\n"                    // 7
    "diameter = 2.0e-3\n"                  // 8
    "density = 2500.0\n"                   // 9
    "[[inflow]]\n"                         // 10
    "name = \"feed\"\n"                    // 11
    "species = \"bead\"\n"                 // 12
    "axis = \"z\"\n"                       // 13
    "plane = 0.095\n"                      // 14
    "side = \"below\"\n"                   // 15
    "min = [0.0, 0.0, 0.0]\n"              // 16
    "max = [0.02, 0.01, 0.0]\n"            // 17
    "mass_flow = 0.002\n"                  // 18
    "velocity = [0.0, 0.0, -1.5]\n"        // 19
    "velocity_spread = [0.1, 0.1, 0.2]\n"  // 20
    "[[outflow]]\n"                        // 21
    "axis = \"z\"\n"                       // 22
    "plane = 0.005\n"                      // 23
    "side = \"below\"\n"                   // 24
    "[time]\n"                             // 25
    "end = 0.1\n";                         // 26

}  // namespace

TEST(FlowScene, ReadsInflowsOutflowsAndDefaults) {
  const Scene scene = parse_scene(kDuct, "duct.toml");
  ASSERT_EQ(scene.flow.inflows.size(), 1u);
  ASSERT_EQ(scene.flow.outflows.size(), 1u);
  const Inflow& in = scene.flow.inflows[0];
  EXPECT_EQ(in.name, "feed");
  EXPECT_EQ(in.species, 0u);
  EXPECT_EQ(in.axis, 2);
  EXPECT_EQ(in.plane, 0.095);
  EXPECT_EQ(in.direction, -1);
  EXPECT_EQ(in.upper, Vec3(0.02, 0.01, 0.0));
  EXPECT_EQ(in.mass_flow, 0.002);
  EXPECT_EQ(in.velocity, Vec3(0.0, 0.0, -1.5));
  EXPECT_EQ(in.velocity_spread, Vec3(0.1, 0.1, 0.2));
  EXPECT_EQ(in.depth, 0.0);  // resolved by FlowBoundaries: max(2 d, 1.5 m/s 1 ms + d) = 4 mm
  EXPECT_EQ(in.attempts, 100);
  const Outflow& out = scene.flow.outflows[0];
  EXPECT_EQ(out.name, "outflow_1");
  EXPECT_EQ(out.axis, 2);
  EXPECT_EQ(out.plane, 0.005);
  EXPECT_EQ(out.direction, -1);
  EXPECT_EQ(scene.flow.interval, 1e-3);  // no gas
  EXPECT_TRUE(scene.flow.any());
  // Without [[inflow]] or [[outflow]]: none.
  const std::string plain = kDuct.substr(0, kDuct.find("[[inflow]]")) + "[time]\nend = 0.1\n";
  EXPECT_FALSE(parse_scene(plain, "plain.toml").flow.any());
}

TEST(FlowScene, IntervalDefaultsToTheGasStepAndMustBeAWholeMultipleOfIt) {
  const std::string gas =
      kDuct + "[gas]\ncoupling = \"one_way\"\ncells = [1, 1, 10]\ntime_step = 2e-4\n";  // 27-30
  EXPECT_EQ(parse_scene(gas, "gas.toml").flow.interval, 2e-4);
  EXPECT_DOUBLE_EQ(parse_scene(gas + "[flow]\ninterval = 1e-3\n", "gas.toml").flow.interval, 1e-3);
  expect_parse_error(gas + "[flow]\ninterval = 3e-4\n",
                     {"bad.toml:32", "flow.interval = 3e-04", "whole multiple of the gas time step",
                      "gas.time_step = 2e-04"});
  expect_parse_error(gas + "[flow]\ninterval = 1e-4\n",
                     {"bad.toml:32", "flow.interval", "whole multiple"});
  expect_parse_error(kDuct + "[flow]\ninterval = 0.0\n",
                     {"bad.toml:28", "flow.interval = 0 ", "(0, inf)"});
  expect_parse_error(
      kDuct + "[flow]\nintervall = 1e-3\n",
      {"bad.toml:28", "unknown key 'flow.intervall'", "did you mean 'flow.interval'"});
}

TEST(FlowScene, MistakesNameFileLineKeyAndRange) {
  // Planes: strictly inside the domain, on a walled axis.
  expect_parse_error(replace(kDuct, "plane = 0.095", "plane = 0.1"),
                     {"bad.toml:14", "inflow[0].plane = 0.1", "not strictly inside", "(0, 0.1)"});
  expect_parse_error(replace(kDuct, "plane = 0.005", "plane = -0.5"),
                     {"bad.toml:23", "outflow[0].plane = -0.5", "not strictly inside"});
  expect_parse_error(replace(kDuct, "axis = \"z\"\nplane = 0.005", "axis = \"y\"\nplane = 0.005"),
                     {"bad.toml:22", "outflow[0].axis = \"y\"", "periodic axis"});
  expect_parse_error(replace(kDuct, "axis = \"z\"\nplane = 0.095", "axis = \"w\"\nplane = 0.095"),
                     {"bad.toml:13", "inflow[0].axis = \"w\"", "\"x\", \"y\", \"z\""});
  // Sides, species, rates.
  expect_parse_error(replace(kDuct, "side = \"below\"\nmin", "min"),
                     {"bad.toml:10", "inflow[0].side", "missing", "\"above\", \"below\""});
  expect_parse_error(replace(kDuct, "side = \"below\"\n[time]", "side = \"down\"\n[time]"),
                     {"bad.toml:24", "outflow[0].side = \"down\"", "\"above\", \"below\""});
  expect_parse_error(replace(kDuct, "species = \"bead\"", "species = \"beads\""),
                     {"bad.toml:12", "inflow[0].species = \"beads\"", "did you mean \"bead\""});
  expect_parse_error(replace(kDuct, "mass_flow = 0.002", "mass_flow = -1.0"),
                     {"bad.toml:18", "inflow[0].mass_flow = -1 ", "(0, inf)", "kg/s"});
  expect_parse_error(
      replace(kDuct, "velocity_spread = [0.1, 0.1, 0.2]", "velocity_spread = [0.1, -0.1, 0.2]"),
      {"bad.toml:20", "inflow[0].velocity_spread", "[0, inf)"});
  expect_parse_error(replace(kDuct, "mass_flow = 0.002", "mass_flow = 0.002\nattempts = 0"),
                     {"bad.toml:19", "inflow[0].attempts = 0", "[1, 1000000]"});
  // The rectangle and the slab.
  expect_parse_error(replace(kDuct, "max = [0.02, 0.01, 0.0]", "max = [0.03, 0.01, 0.0]"),
                     {"bad.toml:17", "inflow[0].max = ", "not inside the domain", "[0, 0.02]"});
  expect_parse_error(replace(kDuct, "max = [0.02, 0.01, 0.0]", "max = [0.0, 0.01, 0.0]"),
                     {"bad.toml:17", "inflow[0].max", "must exceed min"});
  expect_parse_error(
      replace(kDuct, "mass_flow = 0.002", "mass_flow = 0.002\ndepth = 0.001"),
      {"bad.toml:19", "inflow[0].depth = 0.001", "too thin for one particle", "0.002 m"});
  expect_parse_error(replace(kDuct, "mass_flow = 0.002", "mass_flow = 0.002\ndepth = 0.0999"),
                     {"bad.toml:19", "inflow[0].depth = 0.0999", "reaches outside the domain"});
  expect_parse_error(replace(kDuct, "plane = 0.005", "plane = 0.093"),
                     {"bad.toml:14", "inflow[0].plane = 0.095", "beyond outflow \"outflow_1\""});
  // Unknown keys, duplicate names.
  expect_parse_error(replace(kDuct, "mass_flow = 0.002", "mass_rate = 0.002"),
                     {"bad.toml:10", "inflow[0].mass_flow", "missing"});
  expect_parse_error(replace(kDuct, "mass_flow = 0.002", "mass_flow = 0.002\nrate = 1"),
                     {"bad.toml:19", "unknown key 'inflow[0].rate'"});
  expect_parse_error(
      kDuct + "[[outflow]]\nname = \"outflow_1\"\naxis = \"x\"\nplane = 0.001\nside = \"below\"\n",
      {"bad.toml:28", "outflow[1].name = \"outflow_1\"", "earlier outflow"});
}
