// Impacts: the collisions whose normal approach speed exceeds the scene's impact speed
// (events/statistics.hpp, scenarios/scene/impact_speed.hpp), counted by every method.
//
// - A head-on pair and a fall onto a wall, at a speed just above and just below the impact
//   speed, in each method that resolves them deterministically: the count is exact.
// - An elastic gas in equilibrium, event-driven and Monte Carlo: the share of its collisions
//   that are impacts against kinetic theory's exp(-v*^2 / (2 (theta_s + theta_t))) (the
//   analysis' impact_share), with a tolerance of four binomial standard errors.
// - impact_share against a numerical integration of its defining integrals.
// - The scene's default and its errors.
// The event-driven count is also checked collision for collision against a brute-force code in
// tests/test_collision_count.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <cstdio>
#include <memory>
#include <string>

#include "events/method_factory.hpp"
#include "scenarios/analysis/local_fields.hpp"
#include "scenarios/scene/impact_speed.hpp"
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {
namespace {

std::string number(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

/// The [method] part of a scene for `method`: soft spheres need elastic constants and a step.
std::string method_text(const std::string& method) {
  if (method == "soft_sphere")
    return "[method]\nkind = \"soft_sphere\"\n[soft_sphere]\ncontact_model = \"hertz_mindlin\"\n"
           "step_fraction = 0.02\n";
  return "[method]\nkind = \"" + method + "\"\n";
}

/// The gas scene's [method]: Monte Carlo with the cell's own particles as partners (see
/// ImpactShare).
std::string gas_method_text(const std::string& method) {
  if (method == "monte_carlo") return method_text(method) + "[monte_carlo]\npartner = \"cell_particle\"\n";
  return method_text(method);
}

/// Glass beads of 10 mm (soft spheres: 1e7 Pa) in a closed 0.2 m box without gravity, elastic
/// and smooth, with `particles` listed and the impact speed v_star.
std::string box_scene(const std::string& method, double v_star, const std::string& particles) {
  return "[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [0.2, 0.2, 0.2]\ngravity = [0.0, 0.0, 0.0]\n"
         "[[species]]\nname = \"bead\"\ndiameter = 0.01\ndensity = 2500.0\n"
         "young_modulus = 1.0e7\npoisson_ratio = 0.3\n"
         "[collisions]\ndefault = { e = 1.0, mu = 0.0, beta0 = -1.0 }\n" +
         method_text(method) + "[time]\nend = 1.0\n[analysis]\nimpact_speed = " + number(v_star) +
         "\n" + particles;
}

std::string particle(double x, double y, double z, double vx, double vz) {
  return "[[particles]]\nspecies = \"bead\"\nposition = [" + number(x) + ", " + number(y) + ", " +
         number(z) + "]\nvelocity = [" + number(vx) + ", 0.0, " + number(vz) + "]\n";
}

/// Runs `text` to t_end and returns its counters.
RunStatistics run_scene(const std::string& text, double t_end) {
  Scene scene = parse_scene(text, "impacts.toml");
  build_initial_state(scene);
  std::unique_ptr<CollisionMethod> method = make_method(scene.system, scene.method);
  EXPECT_TRUE(method->run_until(t_end));
  return method->statistics();
}

class DeterministicImpacts : public ::testing::TestWithParam<std::string> {};

// Two beads 10 mm apart closing at 0.2 m/s touch at t = 0.025 s and part; the nearest wall is
// 0.14 m away, so by t = 0.2 s there is one pair collision and no wall collision. At an impact
// speed of 0.19 m/s it is an impact, at 0.21 m/s it is not.
TEST_P(DeterministicImpacts, AHeadOnPairIsAnImpactOnlyAboveTheImpactSpeed) {
  const std::string pair =
      particle(0.085, 0.1, 0.1, 0.1, 0.0) + particle(0.115, 0.1, 0.1, -0.1, 0.0);
  for (const double v_star : {0.19, 0.21}) {
    const RunStatistics st = run_scene(box_scene(GetParam(), v_star, pair), 0.2);
    EXPECT_EQ(st.pair(0, 0), 1u) << "v* = " << v_star;
    EXPECT_EQ(st.pair_impact(0, 0), v_star < 0.2 ? 1u : 0u) << "v* = " << v_star;
    EXPECT_EQ(st.wall_events, 0u);
  }
}

// A bead falling (without gravity) at 0.2 m/s onto the floor 0.045 m below touches it at
// t = 0.225 s; by 0.4 s it has hit only the floor, once.
TEST_P(DeterministicImpacts, AWallHitIsAnImpactOnlyAboveTheImpactSpeed) {
  const std::string one = particle(0.1, 0.1, 0.05, 0.0, -0.2);
  for (const double v_star : {0.19, 0.21}) {
    const RunStatistics st = run_scene(box_scene(GetParam(), v_star, one), 0.4);
    EXPECT_EQ(st.wall_events, 1u) << "v* = " << v_star;
    std::uint64_t impacts = 0;
    for (std::size_t w = 0; w < st.wall_count; ++w) impacts += st.wall_impact(0, w);
    EXPECT_EQ(impacts, v_star < 0.2 ? 1u : 0u) << "v* = " << v_star;
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, DeterministicImpacts,
                         ::testing::Values("event_driven", "soft_sphere"));

// Monte Carlo's walls are exact (its pairs are drawn: see ImpactShare below).
TEST(MonteCarloImpacts, AWallHitIsAnImpactOnlyAboveTheImpactSpeed) {
  const std::string one = particle(0.1, 0.1, 0.05, 0.0, -0.2);
  for (const double v_star : {0.19, 0.21}) {
    const RunStatistics st = run_scene(box_scene("monte_carlo", v_star, one), 0.4);
    EXPECT_EQ(st.wall_events, 1u) << "v* = " << v_star;
    std::uint64_t impacts = 0;
    for (std::size_t w = 0; w < st.wall_count; ++w) impacts += st.wall_impact(0, w);
    EXPECT_EQ(impacts, v_star < 0.2 ? 1u : 0u) << "v* = " << v_star;
  }
}

/// A gas for ImpactShare: its method, particle count and solid fraction.
struct GasCase {
  std::string method;
  int count;
  double solid_fraction;
};
void PrintTo(const GasCase& c, std::ostream* out) {
  *out << c.method << ", " << c.count << " spheres at phi = " << c.solid_fraction;
}

class ImpactShare : public ::testing::TestWithParam<GasCase> {};

/// theta = <|v|^2> / 3 of the particles now (m = 1 kg, no mean flow to speak of), m^2/s^2.
double velocity_variance(const CollisionMethod& method) {
  double sum = 0.0;
  for (std::size_t i = 0; i < method.particle_count(); ++i) sum += method.velocity(i).squaredNorm();
  return sum / (3.0 * static_cast<double>(method.particle_count()));
}

// An elastic, smooth gas (m = 1 kg, T = 1 J: theta = 1 m^2/s^2 per component) in a periodic
// box. In equilibrium the normal approach speed w of the collisions is distributed as
// w exp(-w^2 / (2 sigma^2)), sigma^2 = theta + theta, so the share above v* is
// impact_share(v*, 2 theta) = exp(-v*^2 / (4 theta)); v* = sqrt(4 ln 2) makes it 1/2 at
// theta = 1, where a wrong variance (theta instead of 2 theta, a missing factor 2 in the
// exponent) moves it to 1/4 or 0.71. The run goes in ten stretches and kinetic theory is taken
// at each stretch's mean theta, so that a slow drift of the temperature does not count against
// the count. Event-driven: 1000 spheres at phi = 0.05. Monte Carlo: 10 000 at phi = 0.005, with
// the cell's own particles as partners ([monte_carlo] partner = "cell_particle"). (At
// phi = 0.05 the Monte Carlo gas cooled by 8 % in 100 s with either partner model and its share
// came out 0.428 against 0.458 at its own temperature: a property of the method at that
// density, which its own tests and charts treat, not of the impact count.) About 35 000
// collisions: the binomial standard error of the share is 0.0027, and the tolerance is four of
// them (the collisions of one particle are weakly correlated; a finite gas's velocities are
// Maxwellian to O(1/N)).
TEST_P(ImpactShare, EquilibriumGasMatchesKineticTheory) {
  const GasCase& c = GetParam();
  const double v_star = std::sqrt(4.0 * std::log(2.0));
  const double edge = std::cbrt(c.count * std::numbers::pi / 6.0 / c.solid_fraction);
  const std::string text =
      "[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [" + number(edge) + ", " + number(edge) + ", " +
      number(edge) + "]\nperiodic = [\"x\", \"y\", \"z\"]\ngravity = [0.0, 0.0, 0.0]\n"
      "[[species]]\nname = \"grain\"\ndiameter = 1.0\ndensity = 1.909859317102744\n"
      "fill = { count = " + std::to_string(c.count) + ", arrangement = \"random\" }\n"
      "[collisions]\ndefault = { e = 1.0, mu = 0.0, beta0 = -1.0 }\n" +
      gas_method_text(c.method) + "[initial]\nseed = 3\ntemperature = 1.0\n[time]\nend = 100.0\n" +
      "[analysis]\nimpact_speed = " + number(v_star) + "\n";
  Scene scene = parse_scene(text, "gas.toml");
  build_initial_state(scene);
  std::unique_ptr<CollisionMethod> method = make_method(scene.system, scene.method);
  ASSERT_NEAR(impact_share(v_star, 2.0), 0.5, 1e-15);
  double expected_impacts = 0.0, theta = velocity_variance(*method);
  const double theta_start = theta;
  std::uint64_t collisions = 0;
  for (int stretch = 1; stretch <= 10; ++stretch) {
    ASSERT_TRUE(method->run_until(10.0 * stretch));
    const double theta_end = velocity_variance(*method);
    const std::uint64_t now = method->statistics().pair(0, 0);
    expected_impacts += double(now - collisions) * impact_share(v_star, theta + theta_end);
    collisions = now;
    theta = theta_end;
  }
  ASSERT_GT(collisions, 25000u);
  const double share = double(method->statistics().pair_impact(0, 0)) / double(collisions);
  const double expected = expected_impacts / double(collisions);
  const double tolerance = 4.0 * std::sqrt(expected * (1.0 - expected) / double(collisions));
  std::printf("%s: %llu collisions, theta %.4f -> %.4f, impact share %.4f (kinetic theory %.4f, "
              "tolerance %.4f)\n",
              c.method.c_str(), static_cast<unsigned long long>(collisions), theta_start, theta,
              share, expected, tolerance);
  EXPECT_NEAR(share, expected, tolerance);
}

INSTANTIATE_TEST_SUITE_P(Methods, ImpactShare,
                         ::testing::Values(GasCase{"event_driven", 1000, 0.05},
                                           GasCase{"monte_carlo", 10000, 0.005}));

// impact_share(v*, sigma^2) = int_v*^inf w f(w) dw / int_0^inf w f(w) dw with f Gaussian of
// variance sigma^2, here by the midpoint rule on [0, v*] and [v*, 12 sigma] with 1e5 intervals
// each (the tail beyond 12 sigma is below 1e-31; the rule's error about 1e-10 relative): they
// agree to 1e-8 relative.
TEST(ImpactShareFormula, MatchesTheIntegralItStandsFor) {
  const auto midpoint = [](double a, double b, double variance) {
    const int n = 100000;
    const double h = (b - a) / n;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
      const double w = a + (k + 0.5) * h;
      sum += w * std::exp(-w * w / (2.0 * variance));
    }
    return sum * h;
  };
  for (const double variance : {0.01, 1.0, 7.0})
    for (const double v_star : {0.0, 0.03, 0.3, 1.0, 2.5}) {
      const double top = 12.0 * std::sqrt(variance);
      if (v_star >= top) continue;
      const double above = midpoint(v_star, top, variance);
      const double below = midpoint(0.0, v_star, variance);
      const double expected = above / (above + below);
      EXPECT_NEAR(impact_share(v_star, variance), expected, 1e-8 * expected + 1e-300)
          << "sigma^2 = " << variance << ", v* = " << v_star;
    }
  EXPECT_EQ(impact_share(0.0, 0.0), 1.0);
  EXPECT_EQ(impact_share(0.1, 0.0), 0.0);
}

// The default: kImpactSpeedFraction sqrt(|g| d_min) under gravity, 0 without; a scene's own
// value; a negative one refused with the key and its range.
TEST(ImpactSpeedScene, DefaultFollowsGravityAndTheSmallestBead) {
  const std::string species =
      "[[species]]\nname = \"large\"\ndiameter = 1.0e-3\ndensity = 2500.0\n"
      "[[species]]\nname = \"fines\"\ndiameter = 0.333e-3\ndensity = 2500.0\n[time]\nend = 1.0\n";
  const std::string box = "[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [0.01, 0.01, 0.01]\n";
  const Scene falling = parse_scene(box + "gravity = [0.0, 0.0, -9.81]\n" + species, "a.toml");
  EXPECT_DOUBLE_EQ(falling.system.impact_speed, 0.1 * std::sqrt(9.81 * 0.333e-3));
  EXPECT_EQ(falling.system.impact_speed, default_impact_speed(falling.system));
  const Scene floating = parse_scene(box + "gravity = [0.0, 0.0, 0.0]\n" + species, "b.toml");
  EXPECT_EQ(floating.system.impact_speed, 0.0);
  const Scene own = parse_scene(
      box + "gravity = [0.0, 0.0, -9.81]\n" + species + "[analysis]\nimpact_speed = 0.02\n",
      "c.toml");
  EXPECT_EQ(own.system.impact_speed, 0.02);
  try {
    parse_scene(box + species + "[analysis]\nimpact_speed = -0.1\n", "d.toml");
    FAIL() << "a negative impact speed was accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("d.toml"), std::string::npos) << message;
    EXPECT_NE(message.find("impact_speed"), std::string::npos) << message;
    EXPECT_NE(message.find("[0, inf)"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace carom
