// Initial states from elsewhere: particles read back from a run file or a checkpoint
// (initial.from_file) and beds settled before t = 0 (initial.settle_time).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "events/event_driven/engine.hpp"
#include "scenarios/run/run_output.hpp"
#include "scenarios/scene/scene.hpp"
#include "tests/scene_support.hpp"

using namespace carom;
using test::error_of;
namespace fs = std::filesystem;

namespace {

/// A walled box with gravity and a frictional, dissipative bead species (TC on). Line numbers
/// matter for the error tests: [initial] is appended at line 12.
std::string column_scene(const std::string& species_name, double diameter, const std::string& fill) {
  return "[domain]\n"                                                      // 1
         "min = [0.0, 0.0, 0.0]\n"                                         // 2
         "max = [0.01, 0.01, 0.04]\n"                                      // 3
         "gravity = [0.0, 0.0, -9.81]\n"                                   // 4
         "[[species]]\n"                                                   // 5
         "name = \"" + species_name + "\"\n"                               // 6
         "diameter = " + format_number(diameter) + "\n"                    // 7
         "density = 2500.0\n" +                                            // 8
         fill +                                                            // 9
         "[collisions]\n"                                                  // 10
         "default = { e = 0.7, mu = 0.3, beta0 = 0.2 }\n"                  // 11
         "collapse = { model = \"tc\", contact_time = 1e-5 }\n"            // 12
         "[time]\n"                                                        // 13
         "end = 0.1\n";                                                    // 14
}

const std::string kFill = "fill = { count = 50 }\n";
const std::string kNoFill = "\n";

/// A scratch folder per test, removed at the end.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    path = fs::temp_directory_path() /
           ("carom_placement_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() { fs::remove_all(path); }
};

/// Runs the 50-bead column (random placement, some temperature) for `time` s and writes its
/// run file (snapshots at 0 and at `time`) and a checkpoint into dir. Returns the simulator.
EventDrivenEngine run_and_write(const fs::path& dir, double time) {
  Scene scene = parse_scene(column_scene("bead", 1e-3, kFill) + "[initial]\ntemperature = 1e-9\n", "source.toml");
  build_initial_state(scene);
  EventDrivenEngine sim(scene.system, scene.method.event_driven);
  const RunInfo info{scene.text, scene.name, scene.seed};
  RunFile file((dir / "run.h5").string(), info, sim.system());
  file.write_snapshot(sim);
  sim.run_until(time);
  file.write_snapshot(sim);
  write_checkpoint((dir / "checkpoint.h5").string(), sim, info);
  return sim;
}

/// The state as a run reports it, in id order.
std::vector<std::size_t> id_order(const EventDrivenEngine& sim) {
  std::vector<std::size_t> order(sim.particle_count());
  for (std::size_t i = 0; i < order.size(); ++i) order[sim.system().particles.id[i]] = i;
  return order;
}

void expect_fragments(const std::string& message, const std::vector<std::string>& fragments) {
  ASSERT_FALSE(message.empty()) << "accepted";
  for (const auto& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

}  // namespace

// ---- initial.from_file ---------------------------------------------------------------------

// Reading back is a copy, not a recomputation: every double must come back bit for bit, from the
// last snapshot of a run file and from a checkpoint (whose delayed states are advanced exactly
// as EventDrivenEngine::position does), so that a bed settled once is the same bed in every reuse.
TEST(FromFile, RunFileAndCheckpointRoundTripBitForBit) {
  ScratchDir dir;
  const EventDrivenEngine sim = run_and_write(dir.path, 0.02);
  const std::vector<std::size_t> order = id_order(sim);
  for (const std::string source : {"run.h5", "checkpoint.h5"}) {
    SCOPED_TRACE(source);
    // A relative path is relative to the scene file's folder.
    Scene scene = parse_scene(column_scene("bead", 1e-3, kNoFill) + "[initial]\nfrom_file = { path = \"" + source + "\" }\n",
                              (dir.path / "reuse.toml").string());
    build_initial_state(scene);
    const ParticleStore& p = scene.system.particles;
    ASSERT_EQ(p.size(), sim.particle_count());
    for (std::size_t k = 0; k < p.size(); ++k) {
      const std::size_t i = order[k];
      EXPECT_EQ(p.id[k], k);
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(p.position[k][c], sim.position(i)[c]) << "particle " << k;
        EXPECT_EQ(p.velocity[k][c], sim.velocity(i)[c]) << "particle " << k;
        EXPECT_EQ(p.spin[k][c], sim.spin(i)[c]) << "particle " << k;
      }
      EXPECT_EQ(p.species[k], 0u);
    }
    EXPECT_NO_THROW(EventDrivenEngine(scene.system, scene.method.event_driven));
  }
  // snapshot = 0 is the placed state at t = 0; a fill is placed around the file's particles.
  Scene first = parse_scene(column_scene("bead", 1e-3, "fill = { count = 10 }\n") +
                                "[initial]\nfrom_file = { path = \"" + (dir.path / "run.h5").string() + "\", snapshot = 0 }\n",
                            "first.toml");
  build_initial_state(first);
  EXPECT_EQ(first.system.particles.size(), 60u);
}

TEST(FromFile, SpeciesAndRadiusMismatchNameFileLineAndKey) {
  ScratchDir dir;
  run_and_write(dir.path, 0.005);
  const std::string from = "[initial]\nfrom_file = { path = \"" + (dir.path / "run.h5").string() + "\" }\n";  // line 16
  // The file's species "bead" is not in a scene that only knows "glass".
  expect_fragments(error_of(column_scene("glass", 1e-3, kNoFill) + from),
                   {"bad.toml:16", "initial.from_file.path", "run.h5", "\"bead\"", "\"glass\"", "matched by name"});
  // Same name, other diameter: the radius stored in the file must be diameter / 2 exactly.
  expect_fragments(error_of(column_scene("bead", 1.2e-3, kNoFill) + from),
                   {"bad.toml:16", "initial.from_file.path", "has radius 5e-04 m", "diameter 0.0012 m",
                    "species.bead.diameter = 0.001"});
  // Checkpoints work on the same terms.
  expect_fragments(error_of(column_scene("glass", 1e-3, kNoFill) + "[initial]\nfrom_file = { path = \"" +
                            (dir.path / "checkpoint.h5").string() + "\" }\n"),
                   {"bad.toml:16", "checkpoint", "\"bead\"", "\"glass\""});
}

TEST(FromFile, BadPathsAndSnapshots) {
  ScratchDir dir;
  run_and_write(dir.path, 0.005);
  const std::string run = (dir.path / "run.h5").string();
  expect_fragments(error_of(column_scene("bead", 1e-3, kNoFill) + "[initial]\nfrom_file = { path = \"nothing.h5\" }\n"),
                   {"bad.toml:16", "initial.from_file.path = \"nothing.h5\"", "no such file", "relative"});
  expect_fragments(error_of(column_scene("bead", 1e-3, kNoFill) + "[initial]\nfrom_file = { path = \"" + run +
                            "\", snapshot = 2 }\n"),
                   {"bad.toml:16", "snapshot = 2 is out of range", "holds 2 snapshots"});
  expect_fragments(error_of(column_scene("bead", 1e-3, kNoFill) + "[initial]\nfrom_file = { path = \"" +
                            (dir.path / "checkpoint.h5").string() + "\", snapshot = 0 }\n"),
                   {"bad.toml:16", "no snapshots"});
  expect_fragments(error_of(column_scene("bead", 1e-3, kNoFill) + "[initial]\nfrom_file = { path = \"" + run +
                            "\", time = 0 }\n"),
                   {"bad.toml:16", "initial.from_file.time"});
  // A box too small for the file's particles: the one poking through a wall is named by its row.
  std::string small = column_scene("bead", 1e-3, kNoFill);
  small.replace(small.find("0.04]"), 5, "0.01]");
  expect_fragments(error_of(small + "[initial]\nfrom_file = { path = \"" + run + "\" }\n"),
                   {"bad.toml: initial state", "of initial.from_file (bad.toml:16)", "lies outside the domain"});
}

// ---- initial.settle_time -------------------------------------------------------------------

// 50 beads dropped from the upper half of a 10 x 10 x 40 mm box come to rest: after 0.3 s (four
// free-fall times of the 20 mm drop) every bead is inside the box, the kinetic energy left is a
// small fraction of the potential energy released (dissipative collisions at e = 0.7 remove it
// within a few bounces; 5 % leaves room for the TC model's elastic collisions in the bed), and
// the state passes the engine's validation.
TEST(Settling, SmallColumnComesToRest) {
  const std::string scene_text =
      column_scene("bead", 1e-3, "fill = { count = 50, region = \"top\" }\n") +
      "[regions.top]\nmin = [0.0, 0.0, 0.02]\nmax = [0.01, 0.01, 0.04]\n[initial]\nsettle_time = 0.3\n";
  Scene placed = parse_scene(scene_text, "column.toml", {"initial.settle_time=0"});
  build_initial_state(placed);
  Scene scene = parse_scene(scene_text, "column.toml");
  build_initial_state(scene);
  const ParticleStore& before = placed.system.particles;
  const ParticleStore& after = scene.system.particles;
  ASSERT_EQ(after.size(), 50u);
  double released = 0.0, kinetic = 0.0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    EXPECT_EQ(after.id[i], i);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(after.position[i][k] - after.radius[i], -1e-10 * after.radius[i]);
      EXPECT_LE(after.position[i][k] + after.radius[i], (k == 2 ? 0.04 : 0.01) + 1e-10 * after.radius[i]);
    }
    released += after.mass[i] * 9.81 * (before.position[i].z() - after.position[i].z());
    kinetic += 0.5 * after.mass[i] * after.velocity[i].squaredNorm() + 0.5 * after.inertia[i] * after.spin[i].squaredNorm();
  }
  EXPECT_GT(released, 0.0);
  EXPECT_LT(kinetic, 0.05 * released) << "kinetic " << kinetic << " J, released " << released << " J";
  EXPECT_NO_THROW(validate_initial_state(scene.system));
  EXPECT_NO_THROW(EventDrivenEngine(scene.system, scene.method.event_driven));

  Scene still = parse_scene(scene_text + "settle_zero_velocity = true\n", "column.toml");
  build_initial_state(still);
  for (std::size_t i = 0; i < still.system.particles.size(); ++i) {
    EXPECT_EQ(still.system.particles.position[i], after.position[i]);  // same run, velocities dropped
    EXPECT_EQ(still.system.particles.velocity[i], Vec3::Zero());
  }
}

// initial.settle_method = "event_driven": a soft-sphere scene settles by exact events (0.12 s:
// the lowest beads land after 0.064 s, so contacts shape the bed), to the
// very state (bit for bit) the event-driven scene settles to, so that a chart's methods start
// from the same bed; without the key the soft spheres settle themselves, to another state.
TEST(Settling, EventDrivenSettlingGivesEveryMethodTheSameBed) {
  const std::string scene_text =
      column_scene("bead", 1e-3, "fill = { count = 50, region = \"top\" }\n") +
      "[regions.top]\nmin = [0.0, 0.0, 0.02]\nmax = [0.01, 0.01, 0.04]\n[initial]\nsettle_time = "
      "0.12\n";
  Scene events = parse_scene(scene_text, "column.toml");
  build_initial_state(events);
  const std::vector<std::string> soft = {"method.kind=\"soft_sphere\"",
                                         "species.bead.young_modulus=1e8"};
  std::vector<std::string> soft_by_events = soft;
  soft_by_events.push_back("initial.settle_method=\"event_driven\"");
  Scene same = parse_scene(scene_text, "column.toml", soft_by_events);
  build_initial_state(same);
  Scene own = parse_scene(scene_text, "column.toml", soft);
  build_initial_state(own);
  const ParticleStore& e = events.system.particles;
  ASSERT_EQ(same.system.particles.size(), e.size());
  ASSERT_EQ(own.system.particles.size(), e.size());
  double moved = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_EQ(same.system.particles.position[i], e.position[i]) << "particle " << i;
    EXPECT_EQ(same.system.particles.velocity[i], e.velocity[i]) << "particle " << i;
    EXPECT_EQ(same.system.particles.spin[i], e.spin[i]) << "particle " << i;
    moved = std::max(moved, (own.system.particles.position[i] - e.position[i]).norm());
  }
  EXPECT_GT(moved, 1e-6) << "the soft-sphere settling should reach another state (m)";
}

TEST(Settling, CollapseNamesTheKeyAndHintsAtContactTime) {
  std::string text = column_scene("bead", 1e-3, "fill = { count = 50, arrangement = \"fcc\" }\n");
  text.replace(text.find("collapse = { model = \"tc\", contact_time = 1e-5 }\n"), 49, "collapse = { stall_collisions = 50 }\n");
  expect_fragments(error_of(text + "[initial]\nsettle_time = 1.0\n"),
                   {"bad.toml:16", "initial.settle_time = 1", "collapse", "contact_time"});
}

TEST(Settling, KeysAreChecked) {
  expect_fragments(error_of(column_scene("bead", 1e-3, kFill) + "[initial]\nsettle_time = -1\n"),
                   {"bad.toml:16", "initial.settle_time = -1", "[0, inf)"});
  expect_fragments(error_of(column_scene("bead", 1e-3, kFill) + "[initial]\nsettle_zero_velocity = true\n"),
                   {"bad.toml:16", "initial.settle_zero_velocity", "settle_time"});
  expect_fragments(
      error_of(column_scene("bead", 1e-3, kFill) + "[initial]\nsettle_method = \"event_driven\"\n"),
      {"bad.toml:16", "initial.settle_method", "settle_time"});
  expect_fragments(error_of(column_scene("bead", 1e-3, kFill) +
                            "[initial]\nsettle_time = 0.1\nsettle_method = \"soft\"\n"),
                   {"bad.toml:17", "initial.settle_method", "\"scene\", \"event_driven\""});
}
