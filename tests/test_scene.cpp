// Scene files: the shipped scenes parse and build; every class of user error is caught before a
// run starts, with a message that names the file, the line, the key, the value and what is
// allowed; --set overrides change the table before validation.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "events/event_driven/engine.hpp"
#include "events/method_factory.hpp"
#include "scenarios/chart/chart_spec.hpp"
#include "scenarios/scene/scene.hpp"
#include "tests/scene_support.hpp"

using namespace carom;
using test::error_of;
using test::expect_error;
using test::replace;

namespace {

/// A small valid scene; tests append to it. Line numbers: [domain] is line 1.
const std::string kBase =
    "[domain]\n"                                 // 1
    "min = [0.0, 0.0, 0.0]\n"                    // 2
    "max = [0.01, 0.01, 0.01]\n"                 // 3
    "[[species]]\n"                              // 4
    "name = \"bead\"\n"                          // 5
    "diameter = 1.0e-3\n"                        // 6
    "density = 2500.0\n"                         // 7
    "fill = { count = 20 }\n"                    // 8
    "[time]\n"                                   // 9
    "end = 0.1\n";                               // 10

}  // namespace

// ---- shipped scenes ------------------------------------------------------------------------

struct ShippedScene {
  const char* file;
  std::size_t particles;  // what the scene's fills produce (documented in the files' comments)
};
/// How ctest lists a case (instead of its bytes).
void PrintTo(const ShippedScene& s, std::ostream* out) { *out << s.file << ", " << s.particles << " particles"; }

class ShippedScenes : public ::testing::TestWithParam<ShippedScene> {};

TEST_P(ShippedScenes, ParseBuildAndValidate) {
  const std::string path = std::string(CAROM_SCENES_DIR) + "/" + GetParam().file;
  Scene scene = load_scene(path);
  build_initial_state(scene);
  EXPECT_EQ(scene.system.particles.size(), GetParam().particles);
  EXPECT_GT(scene.end_time, 0.0);
  if (scene.method.kind == MethodKind::SoftSphere) {
    // Settled as soft spheres: contacts overlap a little (up to max_overlap), which the
    // hard-sphere check would refuse; the scene's own method takes the state.
    EXPECT_NO_THROW(make_method(scene.system, scene.method));
    return;
  }
  EXPECT_NO_THROW(validate_initial_state(scene.system));
  EXPECT_NO_THROW(EventDrivenEngine(scene.system, scene.method.event_driven));
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ShippedScenes,
    ::testing::Values(
        ShippedScene{"elastic_gas.toml", 990}, ShippedScene{"haff_cooling.toml", 1528},
        ShippedScene{"bidisperse_gas.toml", 1049}, ShippedScene{"settling_column.toml", 400},
        ShippedScene{"settling_sphere.toml", 1}, ShippedScene{"packed_bed.toml", 1345},
        ShippedScene{"fluidized_bed.toml", 400}, ShippedScene{"column_1d.toml", 300},
        ShippedScene{"bubbling_bed.toml", 2000}, ShippedScene{"fines_bed.toml", 3207},
        ShippedScene{"hopper.toml", 200}, ShippedScene{"duct_flow.toml", 0},
        ShippedScene{"convergent_duct.toml", 0}, ShippedScene{"convergent_duct_mesh.toml", 0},
        ShippedScene{"convergent_duct_air.toml", 0}, ShippedScene{"narrow_tube.toml", 400}),
    [](const auto& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

// Every shipped chart file reads, and each of its cases makes a valid scene (what a chart
// checks before it runs, without placing the particles).
TEST(ShippedCharts, EveryCaseMakesAScene) {
  for (const char* file : {"dilute_gas_chart.toml", "cloud_drag_chart.toml",
                           "narrow_tube_chart.toml", "fines_bed_chart.toml",
                           "fines_bed_tc_chart.toml"}) {
    const ChartSpec chart = read_chart(std::string(CAROM_SCENES_DIR) + "/" + file);
    const SweepSpec sweep = chart_sweep(chart);
    const std::vector<SweepCase> cases = sweep.cases();
    EXPECT_EQ(cases.size(), chart.variants.size() * chart.seeds.size()) << file;
    for (const SweepCase& c : cases)
      EXPECT_NO_THROW(load_scene(sweep.scene, c.overrides, c.seed, c.origins))
          << file << " case " << c.index;
  }
}

TEST(Scene, ReadsEverySection) {
  const std::string text = kBase +
                           "[meta]\nname = \"demo\"\ndescription = \"all sections\"\n"
                           "[collisions]\n"
                           "default = { e = 0.9, mu = 0.2, beta0 = 0.1 }\n"
                           "walls = { e = 0.8 }\n"
                           "collapse = { model = \"tc\", contact_time = 1e-5 }\n"
                           "[[collisions.wall]]\nwall = \"z_low\"\ne = 0.5\n"
                           "[initial]\nseed = 5\ntemperature = 1e-9\n"
                           "[output]\nsnapshot_every = 0.01\nsample_every = 0.001\ncheckpoint_every = 0.05\n"
                           "[engine]\ngrid_level_ratio = 0.4\nprefetch_from = 50000\n";
  Scene scene = parse_scene(text, "demo.toml");
  EXPECT_EQ(scene.name, "demo");
  EXPECT_EQ(scene.system.walls.size(), 6u);  // no periodic axis: six box walls
  EXPECT_DOUBLE_EQ(scene.system.materials.pair(0, 0).restitution, 0.9);
  // walls inherit mu and beta0 from default, e from walls; z_low is overridden.
  EXPECT_DOUBLE_EQ(scene.system.materials.wall(0, 0).restitution, 0.8);
  EXPECT_DOUBLE_EQ(scene.system.materials.wall(0, 0).friction, 0.2);
  EXPECT_DOUBLE_EQ(scene.system.materials.wall(0, 4).restitution, 0.5);
  EXPECT_EQ(scene.system.walls[4].name, "z_low");
  EXPECT_DOUBLE_EQ(scene.method.event_driven.collapse.contact_time, 1e-5);
  EXPECT_EQ(scene.seed, 5u);
  EXPECT_DOUBLE_EQ(scene.output.checkpoint_every, 0.05);
  EXPECT_DOUBLE_EQ(scene.method.event_driven.grid_level_ratio, 0.4);
  EXPECT_EQ(scene.method.event_driven.prefetch_from, 50000u);
  build_initial_state(scene);
  EXPECT_EQ(scene.system.particles.size(), 20u);
}

// ---- every class of invalid input ---------------------------------------------------------

TEST(SceneErrors, RestitutionAboveOne) {
  expect_error(kBase + "[collisions]\ndefault = { e = 1.2 }\n",
               {"bad.toml:12", "collisions.default.e = 1.2", "outside the allowed range [0, 1]", "normal restitution"});
}

TEST(SceneErrors, NegativeDiameter) {
  expect_error(replace(kBase, "diameter = 1.0e-3", "diameter = -1.0e-3"),
               {"bad.toml:6", "species[0].diameter = -0.001", "(0, inf)", "diameter"});
}

TEST(SceneErrors, NotANumber) {
  expect_error(replace(kBase, "density = 2500.0", "density = nan"),
               {"bad.toml:7", "species[0].density = nan", "not a finite number", "(0, inf)"});
  expect_error(replace(kBase, "density = 2500.0", "density = \"heavy\""), {"bad.toml:7", "not a number"});
}

TEST(SceneErrors, UnknownKeySuggestsClosest) {
  expect_error(replace(kBase, "min = [0.0, 0.0, 0.0]", "min = [0.0, 0.0, 0.0]\ngravty = [0, 0, -9.81]"),
               {"bad.toml:3", "unknown key 'domain.gravty'", "did you mean 'domain.gravity'"});
  expect_error(kBase + "[colisions]\ndefault = { e = 0.9 }\n", {"unknown key 'colisions'", "did you mean 'collisions'"});
  expect_error(kBase + "[collisions]\ndefault = { e = 0.9, muu = 0.1 }\n",
               {"bad.toml:12", "collisions.default.muu", "did you mean 'collisions.default.mu'"});
}

TEST(SceneErrors, WrongChoiceSuggestsClosest) {
  expect_error(kBase + "[collisions]\ncollapse = { model = \"tcc\", contact_time = 1e-5 }\n",
               {"bad.toml:12", "collisions.collapse.model = \"tcc\"", "one of \"none\", \"tc\"", "did you mean \"tc\""});
}

// The lasting-contact limit: 50 collisions within the TC contact time by default; its keys.
TEST(Scene, LastingContactLimit) {
  const auto limit = [](const std::string& collapse) {
    return parse_scene(kBase + "[collisions]\ncollapse = " + collapse + "\n", "good.toml")
        .method.event_driven.collapse.collision_frequency_limit();
  };
  EXPECT_DOUBLE_EQ(limit("{ model = \"tc\", contact_time = 1e-4 }"), 50.0 / 1e-4);
  EXPECT_DOUBLE_EQ(limit("{ model = \"tc\", contact_time = 1e-4, max_collisions_per_contact_time = 10 }"), 1e5);
  EXPECT_DOUBLE_EQ(limit("{ model = \"tc\", contact_time = 1e-4, max_collisions_per_contact_time = 0 }"), 0.0);
  EXPECT_DOUBLE_EQ(limit("{ model = \"tc\", contact_time = 1e-4, max_collision_frequency = 3e4 }"), 3e4);
  EXPECT_DOUBLE_EQ(limit("{ elastic_below_speed = 0.01 }"), 0.0);
  EXPECT_DOUBLE_EQ(limit("{ elastic_below_speed = 0.01, max_collision_frequency = 2e5 }"), 2e5);
}

TEST(SceneErrors, LastingContactLimitKeys) {
  expect_error(kBase + "[collisions]\ncollapse = { max_collisions_per_contact_time = 20 }\n",
               {"bad.toml:12", "collisions.collapse.max_collisions_per_contact_time", "only used with model = \"tc\"",
                "max_collision_frequency"});
  expect_error(kBase + "[collisions]\ncollapse = { model = \"tc\", contact_time = 1e-4, max_collision_frequency = -1 }\n",
               {"bad.toml:12", "collisions.collapse.max_collision_frequency = -1", "[0, inf)"});
}

// [engine] prefetch_from: a count of particles, 0 (hints always) and up; the default is the
// engine's own.
TEST(SceneErrors, PrefetchFromIsACount) {
  EXPECT_EQ(parse_scene(kBase, "good.toml").method.event_driven.prefetch_from, EventDrivenOptions{}.prefetch_from);
  EXPECT_EQ(parse_scene(kBase + "[engine]\nprefetch_from = 0\n", "good.toml").method.event_driven.prefetch_from, 0u);
  expect_error(kBase + "[engine]\nprefetch_from = -1\n", {"bad.toml:12", "engine.prefetch_from = -1", "[0, 1000000000000]"});
  expect_error(kBase + "[engine]\nprefetch_from = 2.5\n", {"bad.toml:12", "engine.prefetch_from", "not an integer"});
}

// [method] selects the collision method by name; the default is the event-driven engine, and a
// name that is not a method is refused with the file, line, key and the allowed names.
TEST(Scene, MethodKindDefaultsToEventDriven) {
  EXPECT_EQ(parse_scene(kBase, "good.toml").method.kind, MethodKind::EventDriven);
  EXPECT_EQ(parse_scene(kBase + "[method]\nkind = \"event_driven\"\n", "good.toml").method.kind,
            MethodKind::EventDriven);
}

TEST(SceneErrors, UnknownMethodNamed) {
  expect_error(kBase + "[method]\nkind = \"event-driven\"\n",
               {"bad.toml:12", "method.kind", "\"event_driven\"", "did you mean \"event_driven\""});
  expect_error(kBase + "[method]\nkind = \"event_driven\"\nstep = 1e-5\n", {"bad.toml:13", "step"});
}

TEST(SceneErrors, FlightAndGasMustFit) {
  expect_error(kBase + "[flight]\nmodel = \"relax\"\n",
               {"bad.toml:12", "flight.model = \"relax\"", "needs a gas", "[gas]"});
  expect_error(kBase + "[gas]\ncoupling = \"two-way\"\n",
               {"bad.toml:12", "gas.coupling", "\"two_way\""});
  expect_error(kBase + "[gas]\ncells = [4, 4, 4]\n[flight]\nmodel = \"ballistic\"\n",
               {"bad.toml:14", "ignores the gas", "\"relax\"", "\"kick\""});
  expect_error(kBase + "[gas]\ncoupling = \"one_way\"\n", {"gas.cells", "missing"});
  expect_error(kBase + "[gas]\ncells = [4, 0, 4]\n", {"bad.toml:12", "gas.cells", "[1, 1e+06]"});
  expect_error(kBase + "[gas]\ncells = [4, 1.5, 4]\n", {"bad.toml:12", "whole numbers"});
  expect_error(kBase + "[gas]\ncells = [4, 4, 4]\ntime_step = -1e-4\n", {"bad.toml:13", "gas.time_step", "(0, inf)"});
  expect_error(kBase + "[gas]\ncells = [4, 4, 4]\ndrag = \"ergun2\"\n", {"bad.toml:13", "gas.drag", "did you mean \"ergun\""});
  expect_error(kBase + "[gas]\ncells = [4, 4, 4]\n[gas.boundaries]\nz_low = \"inlet\"\n",
               {"bad.toml:14", "gas.boundaries.z_low", "needs a velocity"});
  expect_error(kBase + "[gas]\ncells = [4, 4, 4]\n[gas.boundaries]\nz_lo = \"wall\"\n",
               {"unknown key 'gas.boundaries.z_lo'", "did you mean 'gas.boundaries.z_low'"});
  expect_error(replace(kBase, "min = [0.0, 0.0, 0.0]", "min = [0.0, 0.0, 0.0]\nperiodic = [\"x\"]") +
                   "[gas]\ncells = [4, 4, 4]\n[gas.boundaries]\nx_low = \"wall\"\n",
               {"gas.boundaries.x_low", "periodic axis"});
  expect_error(kBase + "[gas]\ncells = [4, 4, 4]\n[flight]\nmodel = \"relax\"\nparticle_step = 1e-4\n",
               {"flight.particle_step", "only used with model = \"kick\""});
}

TEST(Scene, ReadsGasAndFlight) {
  const std::string text = kBase +
                           "[gas]\ncells = [2, 3, 4]\ntime_step = 2e-4\ndrag = \"beetstra\"\n"
                           "[gas.boundaries]\nz_low = { type = \"inlet\", velocity = 0.3, ramp_time = 1.0 }\n"
                           "z_high = \"outlet\"\nx_low = \"wall\"\n"
                           "[flight]\nmodel = \"kick\"\n";
  Scene scene = parse_scene(text, "good.toml");
  EXPECT_EQ(scene.gas.coupling, CouplingLevel::TwoWay);
  EXPECT_EQ(scene.gas.cells, (std::array<int, 3>{2, 3, 4}));
  EXPECT_EQ(scene.gas.closure, DragClosureKind::Beetstra);
  EXPECT_EQ(scene.gas.sides[4].kind, GasSide::Kind::Inlet);
  EXPECT_DOUBLE_EQ(scene.gas.sides[4].velocity, 0.3);
  EXPECT_DOUBLE_EQ(scene.gas.sides[4].ramp_time, 1.0);
  EXPECT_EQ(scene.gas.sides[5].kind, GasSide::Kind::Outlet);
  EXPECT_EQ(scene.gas.sides[0].kind, GasSide::Kind::Wall);
  EXPECT_EQ(scene.gas.sides[1].kind, GasSide::Kind::FreeSlip);
  EXPECT_EQ(scene.flight.model, FlightModel::Kick);
  EXPECT_DOUBLE_EQ(scene.flight.particle_step, 2e-4) << "kick step defaults to the fluid step";
  EXPECT_EQ(scene.method.event_driven.flight_model, FlightModel::Ballistic) << "kicks fly ballistic";
  // A coupled gas without [flight] flies relax.
  Scene relax = parse_scene(kBase + "[gas]\ncells = [2, 3, 4]\n", "good.toml");
  EXPECT_EQ(relax.method.event_driven.flight_model, FlightModel::Relax);
}

TEST(SceneErrors, OverlappingParticlesNamed) {
  const std::string text = replace(kBase, "fill = { count = 20 }\n", "") +
                           "[[particles]]\nspecies = \"bead\"\nposition = [0.005, 0.005, 0.005]\n"
                           "[[particles]]\nspecies = \"bead\"\nposition = [0.0055, 0.005, 0.005]\n";
  expect_error(text, {"bad.toml", "initial state", "particle 0", "particle 1", "overlaps", "bad.toml:10", "bad.toml:13"});
}

TEST(SceneErrors, ParticleThroughAWall) {
  const std::string text = replace(kBase, "fill = { count = 20 }\n", "") +
                           "[[particles]]\nspecies = \"bead\"\nposition = [0.0002, 0.005, 0.005]\n";
  expect_error(text, {"bad.toml", "particle 0", "overlaps wall 'x_low'"});
  const std::string outside = replace(kBase, "fill = { count = 20 }\n", "") +
                              "[[particles]]\nspecies = \"bead\"\nposition = [0.02, 0.005, 0.005]\n";
  expect_error(outside, {"particle 0", "outside the domain"});
}

TEST(SceneErrors, BadContactLaws) {
  expect_error(kBase + "[collisions]\ndefault = { beta0 = 1.5 }\n", {"collisions.default.beta0 = 1.5", "[-1, 1]"});
  expect_error(kBase + "[collisions]\ndefault = { mu = -0.1 }\n", {"collisions.default.mu = -0.1", "[0, inf)"});
  expect_error(kBase + "[collisions]\ndefault = { mu = 0.5, mu_static = 0.2 }\n",
               {"collisions.default.mu_static = 0.2", "[0.5, inf)"});
  expect_error(kBase + "[[collisions.pair]]\nspecies = [\"bead\", \"sand\"]\ne = 0.5\n",
               {"bad.toml:12", "collisions.pair[0].species", "\"sand\", which is no species"});
}

TEST(SceneErrors, StructureAndSyntax) {
  expect_error("[domain\nmin = 1\n", {"bad.toml:1", "not valid TOML"});
  expect_error(replace(kBase, "[time]\nend = 0.1\n", ""), {"[time] section is missing"});
  expect_error(replace(kBase, "end = 0.1", "end = 0"), {"bad.toml:10", "time.end = 0", "(0, inf)"});
  expect_error(replace(kBase, "max = [0.01, 0.01, 0.01]", "max = [0.01, -0.01, 0.01]"), {"bad.toml:3", "domain.max", "must exceed"});
  expect_error(replace(kBase, "max = [0.01, 0.01, 0.01]", "max = [0.01, 0.01]"), {"bad.toml:3", "three numbers"});
  expect_error(kBase + "[domain.extra]\n", {"unknown key 'domain.extra'"});
  expect_error(replace(kBase, "min = [0.0, 0.0, 0.0]", "min = [0.0, 0.0, 0.0]\nperiodic = [\"w\"]"),
               {"domain.periodic", "\"w\""});
}

TEST(SceneErrors, FillsAndRegions) {
  expect_error(replace(kBase, "fill = { count = 20 }", "fill = { count = -3 }"), {"bad.toml:8", "species[0].fill.count = -3", "[1, 100000000]"});
  expect_error(replace(kBase, "fill = { count = 20 }", "fill = { count = 20, volume_fraction = 0.1 }"), {"exactly one of"});
  expect_error(replace(kBase, "fill = { count = 20 }", "fill = { volume_fraction = 0.9 }"), {"volume_fraction = 0.9", "(0, 0.74]"});
  expect_error(replace(kBase, "fill = { count = 20 }", "fill = { region = \"bedd\", count = 2 }") +
                   "[regions.bed]\nmin = [0, 0, 0]\nmax = [0.01, 0.01, 0.005]\n",
               {"species[0].fill.region = \"bedd\"", "did you mean \"bed\""});
  expect_error(kBase + "[regions.bed]\nmin = [0, 0, 0]\nmax = [0.01, 0.01, 0.05]\n", {"bad.toml:13", "regions.bed.max", "outside the domain"});
  expect_error(replace(kBase, "fill = { count = 20 }", "fill = { mass_fraction = 0.5 }"), {"mass fractions", "count or volume_fraction"});
  // Too dense for random insertion: the message points to the lattice.
  expect_error(replace(kBase, "fill = { count = 20 }", "fill = { volume_fraction = 0.6 }"),
               {"bad.toml:8", "placed only", "arrangement = \"fcc\""});
}

TEST(SceneErrors, Analysis) {
  const std::string mixing = kBase + "[analysis]\nmixing = { species = \"bead\", cells = [2, 2, 2] }\n";
  Scene scene = parse_scene(mixing, "a.toml");
  EXPECT_EQ(scene.analysis.mixing_species, 0);
  EXPECT_EQ(scene.analysis.mixing_cells[1], 2);
  EXPECT_EQ(scene.analysis.mixing_region, 0u);  // the whole domain by default
  expect_error(replace(mixing, "species = \"bead\"", "species = \"baed\""),
               {"bad.toml:12", "analysis.mixing.species", "did you mean \"bead\""});
  expect_error(replace(mixing, "cells = [2, 2, 2]", "cells = [2, 0, 2]"), {"analysis.mixing.cells", "[1, 10000]"});
  expect_error(replace(mixing, "cells = [2, 2, 2]", "cells = [2, 1.5, 2]"), {"analysis.mixing.cells", "whole numbers"});
  expect_error(replace(mixing, "cells = [2, 2, 2]", "cells = [2, 2, 2], region = \"bed\""),
               {"analysis.mixing.region = \"bed\"", "names no region"});
  expect_error(kBase + "[analysis]\nmixin = { species = \"bead\" }\n", {"bad.toml:12", "unknown key 'analysis.mixin'"});
  expect_error(kBase + "[analysis]\nfields = { cells = [0, 1, 1] }\n", {"analysis.fields.cells"});
}

TEST(Placement, MassFractionZeroIsNone) {
  // A sweep's reference case: the species exists but has no particles.
  const std::string text = kBase + "[[species]]\nname = \"fine\"\ndiameter = 0.5e-3\ndensity = 2500.0\nfill = { mass_fraction = 0.0 }\n";
  Scene scene = parse_scene(text, "mix.toml");
  EXPECT_EQ(fill_counts(scene)[1], 0u);
  build_initial_state(scene);
  EXPECT_EQ(scene.system.particles.size(), 20u);
  // A tiny non-zero fraction that rounds to no particle is still an error.
  expect_error(replace(text, "mass_fraction = 0.0", "mass_fraction = 1e-9"), {"less than one particle"});
}

// ---- placement ----------------------------------------------------------------------------

TEST(Placement, LatticeReachesHighPacking) {
  // An FCC lattice holds phi = 0.55 in a periodic box, where random insertion would jam.
  const std::string text = replace(replace(kBase, "fill = { count = 20 }", "fill = { volume_fraction = 0.55, arrangement = \"fcc\" }"),
                                   "min = [0.0, 0.0, 0.0]", "min = [0.0, 0.0, 0.0]\nperiodic = [\"x\", \"y\", \"z\"]");
  Scene scene = parse_scene(text, "fcc.toml");
  build_initial_state(scene);  // validates: no overlaps
  const double phi = static_cast<double>(scene.system.particles.size()) * scene.system.species[0].volume() /
                     scene.system.domain.volume();
  EXPECT_NEAR(phi, 0.55, 0.002);
}

TEST(Placement, MassFractionOfAllSolids) {
  // Two species of equal density: 30 % of the solid mass in fines of 1/8 the particle volume.
  const std::string text = kBase + "[[species]]\nname = \"fine\"\ndiameter = 0.5e-3\ndensity = 2500.0\nfill = { mass_fraction = 0.3 }\n";
  Scene scene = parse_scene(text, "mix.toml");
  const auto counts = fill_counts(scene);
  // 20 large of mass m; fines: 0.3 M with M = 20 m / 0.7 -> 0.3 * 20 / 0.7 * 8 = 68.6 -> 69.
  EXPECT_EQ(counts[0], 20u);
  EXPECT_EQ(counts[1], 69u);
  build_initial_state(scene);
  EXPECT_EQ(scene.system.particles.size(), 89u);
}

TEST(Placement, SameSeedSamePlacementOtherSeedOther) {
  Scene a = parse_scene(kBase, "a.toml"), b = parse_scene(kBase, "a.toml"), c = parse_scene(kBase, "a.toml", {}, 99);
  build_initial_state(a);
  build_initial_state(b);
  build_initial_state(c);
  EXPECT_EQ(a.system.particles.position, b.system.particles.position);
  EXPECT_NE(a.system.particles.position, c.system.particles.position);
}

TEST(Placement, TemperatureIsExactAndMomentumZero) {
  Scene scene = parse_scene(kBase + "[initial]\ntemperature = 2e-9\n", "t.toml");
  build_initial_state(scene);
  const ParticleStore& p = scene.system.particles;
  Vec3 momentum = Vec3::Zero();
  double kinetic = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    momentum += p.mass[i] * p.velocity[i];
    kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  }
  EXPECT_LT(momentum.norm(), 1e-12 * std::sqrt(2e-9 * p.mass[0]) * p.size());
  EXPECT_NEAR(kinetic, 1.5 * (p.size() - 1) * 2e-9, 1e-12 * kinetic);
}

// ---- --set overrides ----------------------------------------------------------------------

TEST(Overrides, ChangeValuesBeforeValidation) {
  Scene scene = parse_scene(kBase, "o.toml",
                            {"time.end=0.5", "species.bead.diameter=2e-3", "species.0.density=1000",
                             "collisions.default.e=0.7", "domain.periodic=[\"x\"]", "meta.name=my_run"});
  EXPECT_DOUBLE_EQ(scene.end_time, 0.5);
  EXPECT_DOUBLE_EQ(scene.system.species[0].diameter, 2e-3);
  EXPECT_DOUBLE_EQ(scene.system.species[0].density, 1000.0);
  EXPECT_DOUBLE_EQ(scene.system.materials.pair(0, 0).restitution, 0.7);
  EXPECT_TRUE(scene.system.domain.periodic[0]);
  EXPECT_EQ(scene.name, "my_run");  // not valid TOML, so taken as a string
}

TEST(Overrides, StoredTextReproducesTheScene) {
  // The scene text kept for checkpoints holds the overrides: parsing it again gives the same scene.
  Scene first = parse_scene(kBase, "o.toml", {"collisions.default.e=0.123456789012345678", "time.end=0.25"}, 42);
  Scene again = parse_scene(first.text, "stored");
  EXPECT_EQ(again.system.materials.pair(0, 0).restitution, first.system.materials.pair(0, 0).restitution);
  EXPECT_EQ(again.end_time, 0.25);
  EXPECT_EQ(again.seed, 42u);
}

TEST(Overrides, ErrorsNameTheCommandLine) {
  expect_error(kBase, {"bad.toml (set on the command line)", "collisions.default.e = 3", "[0, 1]"}, {"collisions.default.e=3"});
  expect_error(kBase, {"unknown key 'time.ennd'", "did you mean 'time.end'"}, {"time.ennd=1"});
  expect_error(kBase, {"--set time.end", "expected key=value"}, {"time.end"});
  expect_error(kBase, {"'time.end' is a value, not a table"}, {"time.end.x=1"});
  expect_error(kBase, {"no entry named \"sand\""}, {"species.sand.diameter=1"});
}
