// report.md's "What these numbers depend on" (scenarios/analysis/report_settings.hpp): for each
// method the settings its numbers depend on are named with their values, the gas grid in largest
// diameters, the seed; the TC time's measured effect is quoted only where a TC time is set.
#include <gtest/gtest.h>

#include <string>

#include "scenarios/analysis/report_settings.hpp"
#include "scenarios/scene/scene.hpp"

namespace {

/// A 4 mm x 4 mm x 8 mm box of 1 mm beads with a gas of 2 x 2 x 4 cells (2 diameters each).
const std::string kBed = R"(
[domain]
min = [0, 0, 0]
max = [0.004, 0.004, 0.008]
periodic = ["x", "y"]
gravity = [0, 0, -9.81]
[[species]]
name = "glass"
diameter = 1e-3
density = 2500
young_modulus = 5e7
poisson_ratio = 0.3
fill = { count = 20 }
[collisions]
default = { e = 0.9, mu = 0.1, beta0 = 0.3 }
walls = { e = 0.9, mu = 0.1, beta0 = 0.3 }
collapse = { model = "tc", contact_time = 1e-4 }
[gas]
coupling = "two_way"
density = 1.2
viscosity = 1.8e-5
cells = [2, 2, 4]
time_step = 2e-4
[gas.boundaries]
z_low = { type = "inlet", velocity = 0.5 }
z_high = "outlet"
[initial]
seed = 7
[time]
end = 0.01
)";

/// The section for kBed with `overrides` (--set), without its TC line when `tc` is false.
std::string section(const std::vector<std::string>& overrides, bool tc = true) {
  std::string text = kBed;
  if (!tc) text.erase(text.find("collapse = "), std::string("collapse = { model = \"tc\", contact_time = 1e-4 }\n").size());
  return carom::numerical_settings_section(carom::parse_scene(text, "bed.toml", overrides));
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ReportSettings, EventDrivenNamesTheTcTimeAndQuotesItsMeasuredEffect) {
  const std::string s = section({});
  EXPECT_TRUE(has(s, "## What these numbers depend on")) << s;
  EXPECT_TRUE(has(s, "TC model with a TC time of 1e-04 s")) << s;
  EXPECT_TRUE(has(s, "2 x 2 x 4 cells (2 x 2 x 2 largest diameters), fluid step 2e-04 s")) << s;
  EXPECT_TRUE(has(s, "initial.seed = 7, one run")) << s;
  EXPECT_TRUE(has(s, "not converged in the TC time")) << s;
  EXPECT_TRUE(has(s, "scenarios/scenes/fines_bed_tc_chart.toml")) << s;
  // The impact speed: 0.1 sqrt(9.81 m/s^2 x 1 mm) = 9.905 mm/s.
  EXPECT_TRUE(has(s, "Impacts: collisions faster than v* = 0.009905 m/s")) << s;
}

TEST(ReportSettings, NamesTheImpactSpeedAsSet) {
  const std::string s = section({"analysis.impact_speed=0"});
  EXPECT_TRUE(has(s, "v* = 0 m/s (analysis.impact_speed; 0: every collision is an impact)")) << s;
}

TEST(ReportSettings, WithoutATcTimeNoTcEvidence) {
  const std::string s = section({}, false);
  EXPECT_TRUE(has(s, "no TC model")) << s;
  EXPECT_FALSE(has(s, "TC time")) << s;
}

TEST(ReportSettings, SoftSpheresNameTheirStiffnessAndStep) {
  const std::string s = section({"method.kind=\"soft_sphere\"", "soft_sphere.time_step=1e-6"}, false);
  EXPECT_TRUE(has(s, "soft spheres (Hertz-Mindlin); step 1e-06 s; Young's modulus glass 5e+07 Pa")) << s;
  EXPECT_FALSE(has(s, "TC time")) << s;
}

TEST(ReportSettings, MonteCarloNamesItsStepAndCells) {
  const std::string s = section({"method.kind=\"monte_carlo\""}, false);
  EXPECT_TRUE(has(s, "Monte Carlo collisions; step 0.1 of the shortest mean free time")) << s;
  EXPECT_TRUE(has(s, "contact value none (dilute)")) << s;
}

}  // namespace
