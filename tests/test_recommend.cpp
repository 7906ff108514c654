// The least model a scene needs (scenarios/cli/recommend.hpp): each threshold driven from both
// sides on constructed scenes, and the numbers it rests on against hand computations.
#include <gtest/gtest.h>

#include <cmath>

#include "recommend_support.hpp"
#include "scenarios/cli/recommend.hpp"

namespace carom {
namespace {

using test::placed;

const Advice& topic(const std::vector<Advice>& advice, const std::string& name) {
  for (const Advice& a : advice)
    if (a.topic == name) return a;
  throw std::runtime_error("no advice on " + name);
}

// A gas of 1 mm glass beads at phi = 0.3 with rms speed 1 m/s and Young's modulus E.
Scene bead_gas(double young_modulus) {
  const std::string text = R"(
[domain]
min = [0, 0, 0]
max = [0.01, 0.01, 0.01]
periodic = ["x", "y", "z"]
gravity = [0, 0, 0]
[[species]]
name = "glass"
diameter = 1.0e-3
density = 2500.0
young_modulus = )" + std::to_string(young_modulus) +
                           R"(
fill = { volume_fraction = 0.3 }
[collisions]
default = { e = 0.9, mu = 0.0, beta0 = -1.0 }
[initial]
rms_velocity = 1.0
[time]
end = 0.01
)";
  Scene scene = parse_scene(text, "gas.toml");
  build_initial_state(scene);
  return scene;
}

/// Glass beads of diameter d filling a closed box [0, edge_x] x [0, edge_y] x [0, height] at
/// solid fraction phi, at rest, without gravity.
Scene box_of_beads(double d, double phi, double edge_x, double edge_y, double height) {
  const std::string text = R"(
[domain]
min = [0, 0, 0]
max = [)" + std::to_string(edge_x) +
                           ", " + std::to_string(edge_y) + ", " + std::to_string(height) + R"(]
gravity = [0, 0, 0]
[[species]]
name = "glass"
diameter = )" + std::to_string(d) +
                           R"(
density = 2500.0
fill = { volume_fraction = )" +
                           std::to_string(phi) + R"( }
[collisions]
default = { e = 0.9, mu = 0.0, beta0 = -1.0 }
[time]
end = 0.01
)";
  Scene scene = parse_scene(text, "box.toml");
  build_initial_state(scene);
  return scene;
}

TEST(Recommend, SolidFractionAroundAParticleIsUnbiasedInADiluteGas) {
  // 2000-odd beads placed uniformly at phi = 0.005: a sample cell of 4 diameters holds 0.61 of
  // them on average, so counting the particle itself (the former estimate) read 1 + 1/0.61 = 2.6
  // times too high. Leaving it out, the estimate is the box's fraction within its sampling
  // error: about 1200 pairs share a cell, a relative sd of about 1/sqrt(1200) = 3 %, plus the
  // placement's excluded volume (below 1 % at this fraction). Tolerance 12 %: 4 sd.
  const double d = 1e-3, phi = 0.005;
  const double edge = std::cbrt(2000 * M_PI / 6 * d * d * d / phi);
  const Scene gas = box_of_beads(d, phi, edge, edge, edge);
  ASSERT_GT(gas.system.particles.size(), 1900u);
  const SceneNumbers n = scene_numbers(gas);
  EXPECT_NEAR(n.solid_fraction, phi, 0.02 * phi);
  EXPECT_NEAR(n.solid_fraction_seen / n.solid_fraction, 1.0, 0.12);
}

TEST(Recommend, ContactTimeAgainstMeanFreeTime) {
  // Mean free time (Enskog): omega = 4 n d^2 g0 sqrt(pi / 3) v with n = 6 phi / (pi d^3),
  // g0(0.3) = 2.4781, v = 1 m/s: 1.72e-4 s. Hertz contact time of two 1 mm beads at 1 m/s:
  // 1.02e-4 s at E = 1e7 Pa (tests/VALIDATION.md, "Soft-sphere contacts"), scaling as E^-2/5:
  // 2.6e-6 s at E = 1e11 Pa. Contacts lasting 0.6 of the mean free time are not binary; 0.015 are.
  const Scene soft = bead_gas(1e7), stiff = bead_gas(1e11);
  const SceneNumbers a = scene_numbers(soft), b = scene_numbers(stiff);
  // The scene's rms speed (the fill draws a Maxwellian of that rms and removes its mean motion).
  EXPECT_NEAR(a.speed, 1.0, 0.01);
  // The solid fraction around a particle is the box's 0.3 within the sampling of cells of 4 d.
  EXPECT_NEAR(a.solid_fraction_seen, 0.3, 0.03);
  const double g0 = (1 - a.solid_fraction_seen / 2) / std::pow(1 - a.solid_fraction_seen, 3);
  const double n = 6 * a.solid_fraction_seen / (M_PI * 1e-9);
  EXPECT_NEAR(a.mean_free_time, 1.0 / (4 * n * 1e-6 * g0 * std::sqrt(M_PI / 3.0) * a.speed), 1e-12);
  // tests/VALIDATION.md's example is this pair (E = 1e7 Pa, nu = 0.3, the default) at 1 m/s; t_c
  // scales as v^-1/5.
  EXPECT_NEAR(a.contact_time, 1.0195850e-4 * std::pow(a.speed, -0.2), 1e-10);
  EXPECT_GT(a.contact_time / a.mean_free_time, kContactShare);
  EXPECT_LT(b.contact_time / b.mean_free_time, kContactShare);
  EXPECT_EQ(recommended_method(recommend(soft, a)), MethodKind::SoftSphere);
  EXPECT_EQ(recommended_method(recommend(stiff, b)), MethodKind::EventDriven);
  EXPECT_EQ(topic(recommend(stiff, b), "coupling").choice, "none");
}

TEST(Recommend, PackedBelowMinimumFluidizationFluidizedAbove) {
  // column_1d: 1 mm glass, U_mf 0.56 m/s (Gidaspow blend).
  const Scene fluidized = placed("column_1d.toml", {"gas.boundaries.z_low.velocity=1.0"});
  const Scene packed = placed("column_1d.toml", {"gas.boundaries.z_low.velocity=0.3"});
  const SceneNumbers f = scene_numbers(fluidized), p = scene_numbers(packed);
  ASSERT_GT(f.species[0].minimum_fluidization, 0.3);
  ASSERT_LT(f.species[0].minimum_fluidization, 1.0);
  EXPECT_EQ(f.lasting_share, 0.0);
  EXPECT_EQ(p.lasting_share, 1.0);
  EXPECT_EQ(recommended_method(recommend(fluidized, f)), MethodKind::EventDriven);
  const std::vector<Advice> advice = recommend(packed, p);
  EXPECT_EQ(recommended_method(advice), MethodKind::SoftSphere);
  EXPECT_TRUE(advice.front().differs);  // the scene says event_driven
}

TEST(Recommend, SettlingPilesComeToRestOnlyIfTheyLandBeforeTheEnd) {
  // settling_column: beads fall 0.06 m in vacuum (about 0.11 s) and pile up on the floor.
  const Scene landed = placed("settling_column.toml", {});
  const Scene early = placed("settling_column.toml", {"time.end=0.05"});
  EXPECT_EQ(scene_numbers(landed).lasting_share, 1.0);
  EXPECT_EQ(scene_numbers(early).lasting_share, 0.0);
}

TEST(Recommend, CouplingFromMassLoadingAndStokesNumber) {
  // column_1d holds 300 beads (0.39 g) in 2.3 cm^3 of air: mass loading about 140, two-way.
  const Scene bed = placed("column_1d.toml", {});
  const SceneNumbers b = scene_numbers(bed);
  const double solid = 300 * 2500.0 * M_PI / 6 * 1e-9;
  // The domain is the tube's bounding box (0.006^2 x 0.08 m^3), not the tube.
  EXPECT_NEAR(b.mass_loading, solid / (1.2 * (0.006 * 0.006 * 0.08 - 300 * M_PI / 6 * 1e-9)), 1e-9);
  EXPECT_EQ(topic(recommend(bed, b), "coupling").choice, "two-way");
  // One sphere settling in 3.2 m^3 of air: loading 1e-4, one-way.
  const Scene sphere = placed("settling_sphere.toml", {});
  const SceneNumbers s = scene_numbers(sphere);
  EXPECT_LT(s.mass_loading, kOneWayLoading);
  EXPECT_EQ(topic(recommend(sphere, s), "coupling").choice, "one-way");
  // Beads a thousand times denser in a 5 m/s gas: tau = U_t / g of about 25 s against a flow
  // time of 0.016 s, St > 1e3: the gas cannot steer them.
  const Scene heavy = placed("column_1d.toml",
                             {"species.glass.density=2.5e6", "gas.boundaries.z_low.velocity=5.0"});
  const SceneNumbers h = scene_numbers(heavy);
  EXPECT_GT(h.species[0].stokes, kNoGasStokes);
  EXPECT_NEAR(h.species[0].stokes, h.species[0].relaxation_time * 5.0 / 0.08, 1e-9);
  const Advice coupling = topic(recommend(heavy, h), "coupling");
  EXPECT_EQ(coupling.choice, "none");
  EXPECT_TRUE(coupling.differs);
}

TEST(Recommend, KickFlightsOnlyWhenTheRelaxationTimeSpansManyFluidSteps) {
  // column_1d's beads relax in about 0.69 s: 3450 steps of 2e-4 s, 34 steps of 0.02 s.
  const Scene fine = placed("column_1d.toml", {});
  const Scene coarse = placed("column_1d.toml", {"gas.time_step=0.02", "flight.model=kick"});
  const SceneNumbers f = scene_numbers(fine), c = scene_numbers(coarse);
  EXPECT_GT(f.step_ratio, kKickStepRatio);
  EXPECT_LT(c.step_ratio, kKickStepRatio);
  EXPECT_EQ(topic(recommend(fine, f), "flight").choice, "kick or relax");
  const Advice flight = topic(recommend(coarse, c), "flight");
  EXPECT_EQ(flight.choice, "relax");
  EXPECT_TRUE(flight.differs);
}

TEST(Recommend, GasDimensionsFromTheTubeAndTheBox) {
  // A 6 mm tube of 1 mm beads holds no two cells of 3 diameters across: a 1-D gas; the scene's
  // 1-D column agrees, a 3 x 3 grid across the tube models more than it needs.
  const Scene column = placed("column_1d.toml", {});
  const SceneNumbers a = scene_numbers(column);
  EXPECT_TRUE(a.tube);
  EXPECT_NEAR(a.tube_ratio, 6.0, 1e-12);
  EXPECT_EQ(a.gas_dimensions_needed, 1);
  EXPECT_FALSE(topic(recommend(column, a), "gas grid").differs);
  const Scene cut = placed("column_1d.toml", {"gas.cells=[3, 3, 40]"});
  const SceneNumbers b = scene_numbers(cut);
  EXPECT_EQ(b.gas_dimensions, 3);
  EXPECT_TRUE(topic(recommend(cut, b), "gas grid").differs);
  // fines_bed: 12 mm x 4 mm of 1 mm beads: 2 cells of 3 d fit along x only: 2-D, as it is.
  const Scene bed = placed("fines_bed.toml", {});
  const SceneNumbers c = scene_numbers(bed);
  EXPECT_EQ(c.gas_dimensions_needed, 2);
  EXPECT_FALSE(topic(recommend(bed, c), "gas grid").differs);
}

}  // namespace
}  // namespace carom
