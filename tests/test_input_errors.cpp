// What a new user and a hostile input find, checked at the scene layer: every
// mistake is refused at once, with a message that says what is wrong and what is allowed: a
// directory or a sweep file given as the scene, a negative seed, a value a sweep file set, a
// fill its region cannot hold (refused before anything is allocated), an output that would
// fill the disk.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "scenarios/run/output_estimate.hpp"
#include "scenarios/scene/fill_capacity.hpp"
#include "scenarios/scene/overrides.hpp"
#include "scenarios/scene/scene.hpp"
#include "tests/scene_support.hpp"

using namespace carom;
using test::error_of;
using test::replace;
namespace fs = std::filesystem;

namespace {

/// A box of 1 cm with 20 beads of 1 mm; [domain] is line 1, the fill line 8.
const std::string kBox =
    "[domain]\n"                  // 1
    "min = [0.0, 0.0, 0.0]\n"     // 2
    "max = [0.01, 0.01, 0.01]\n"  // 3
    "[[species]]\n"               // 4
    "name = \"bead\"\n"           // 5
    "diameter = 1.0e-3\n"         // 6
    "density = 2500.0\n"          // 7
    "fill = { count = 20 }\n"     // 8
    "[time]\n"                    // 9
    "end = 0.1\n";                // 10

/// The number after `prefix` in `text` (0 when absent).
std::size_t number_after(const std::string& text, const std::string& prefix) {
  const std::size_t at = text.find(prefix);
  return at == std::string::npos ? 0 : std::stoull(text.substr(at + prefix.size()));
}

}  // namespace

// A directory where the scene file belongs used to read as an empty scene ("[domain] section is
// missing"); it is now named as a directory.
TEST(InputErrors, DirectoryGivenAsSceneFile) {
  const fs::path dir = fs::temp_directory_path() / ("carom_scene_dir_" + std::to_string(getpid()));
  fs::create_directories(dir);
  try {
    load_scene(dir.string());
    ADD_FAILURE() << "a directory was accepted as a scene";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("is a directory, not a scene file"), std::string::npos) << message;
    EXPECT_EQ(message.find("[domain]"), std::string::npos) << message;
  }
  fs::remove_all(dir);
}

// A sweep file given to `carom check` or `carom run` says to use `carom sweep`, instead of
// "unknown key 'sweep'".
TEST(InputErrors, SweepFileGivenAsScene) {
  try {
    parse_scene("[sweep]\nscene = \"fines_bed.toml\"\nseeds = [1, 2]\n", "fines_sweep.toml");
    ADD_FAILURE() << "a sweep file was accepted as a scene";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("fines_sweep.toml:1: this is a sweep file"), std::string::npos) << message;
    EXPECT_NE(message.find("carom sweep fines_sweep.toml"), std::string::npos) << message;
  }
}

// `--seed -1` used to wrap to 2^64 - 1 and be reported as "18446744073709551615 is not an
// integer"; a seed is now checked as written.
TEST(InputErrors, SeedMustBeANonNegativeInteger) {
  EXPECT_EQ(parse_seed("0"), 0u);
  EXPECT_EQ(parse_seed("42"), 42u);
  EXPECT_EQ(parse_seed("9223372036854775807"), 9223372036854775807u);
  for (const char* bad : {"-1", "1.5", "abc", "", "9223372036854775808", "18446744073709551615", "+3", "7x"}) {
    try {
      parse_seed(bad);
      ADD_FAILURE() << "accepted --seed " << bad;
    } catch (const SceneError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("--seed " + std::string(bad) + ": a seed must be a non-negative integer"),
                std::string::npos)
          << message;
      EXPECT_NE(message.find("[0, 9223372036854775807]"), std::string::npos) << message;
    }
  }
}

// A value a sweep file set names the sweep file's line, not "(set on the command line)"; one from
// the command line still says so.
TEST(InputErrors, OverrideFromASweepFileNamesItsLine) {
  try {
    parse_scene(kBox, "scene.toml", {"time.end=-1.0"}, std::nullopt, {"sweep.toml:7"});
    ADD_FAILURE() << "time.end = -1 accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("sweep.toml:7 (for scene.toml): time.end = -1"), std::string::npos) << message;
    EXPECT_EQ(message.find("command line"), std::string::npos) << message;
  }
  try {
    parse_scene(kBox, "scene.toml", {"time.end=-1.0"});
    ADD_FAILURE() << "time.end = -1 accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.toml (set on the command line)"), std::string::npos) << e.what();
  }
  // The stored text (for checkpoints) is the same whichever way the value came.
  EXPECT_EQ(parse_scene(kBox, "s.toml", {"time.end=0.5"}, std::nullopt, {"sweep.toml:7"}).text,
            parse_scene(kBox, "s.toml", {"time.end=0.5"}).text);
}

// 1e8 beads of 1 mm in a 1 cm box used to be refused only after the placement had allocated
// gigabytes and tried for tens of seconds. Now at once, with the largest count that fits:
// 0.64 of 1e-6 m^3 over (pi/6) 1e-9 m^3 = 1222.3.
TEST(InputErrors, ImpossibleRandomFillIsRefusedAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  const std::string message = error_of(replace(kBox, "count = 20", "count = 100000000"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(message.find("bad.toml:8: species[0].fill.count = 100000000"), std::string::npos) << message;
  EXPECT_NE(message.find("at most 1222 fit"), std::string::npos) << message;
  EXPECT_NE(message.find("random close packing"), std::string::npos) << message;
  EXPECT_LT(seconds, 1.0) << "refused, but only after " << seconds << " s";
  // A volume fraction above random close packing, and a mass fraction that implies too many.
  EXPECT_NE(error_of(replace(kBox, "fill = { count = 20 }", "fill = { volume_fraction = 0.7 }"))
                .find("species[0].fill.volume_fraction = 0.7"),
            std::string::npos);
  // Below the bound the placement is still what decides (and names the lattice as the remedy).
  EXPECT_NE(error_of(replace(kBox, "count = 20", "count = 1200")).find("placed only"), std::string::npos);
}

// For a lattice fill the bound is the lattice itself: the count the message gives is placed,
// one more is refused before placement.
TEST(InputErrors, LatticeFillCapacityIsExact) {
  for (const std::string arrangement : {"fcc", "cubic"}) {
    SCOPED_TRACE(arrangement);
    const std::string message = error_of(
        replace(kBox, "count = 20", "count = 100000000, arrangement = \"" + arrangement + "\""));
    EXPECT_NE(message.find("bad.toml:8: species[0].fill.count = 100000000"), std::string::npos) << message;
    EXPECT_NE(message.find(arrangement + " lattice at contact spacing"), std::string::npos) << message;
    const std::size_t capacity = number_after(message, "so at most ");
    ASSERT_GT(capacity, 100u) << message;
    const std::string fits = replace(kBox, "count = 20",
                                     "count = " + std::to_string(capacity) + ", arrangement = \"" + arrangement + "\"");
    EXPECT_EQ(error_of(fits), "") << "the largest count said to fit does not";
    Scene scene = parse_scene(fits, "ok.toml");
    EXPECT_EQ(fill_capacity(scene, 0), capacity);
    const std::string one_more = error_of(replace(
        kBox, "count = 20", "count = " + std::to_string(capacity + 1) + ", arrangement = \"" + arrangement + "\""));
    EXPECT_NE(one_more.find("so at most " + std::to_string(capacity) + " fit"), std::string::npos) << one_more;
  }
}

// output.snapshot_every = 1e-9 over 0.1 s is 1e8 snapshots: refused with the estimate and the key
// that allows it; output.max_bytes raises the limit (and lifts the free-space check).
TEST(InputErrors, RunawayOutputIsRefused) {
  const std::string runaway = kBox + "[output]\nsnapshot_every = 1e-9\n";
  const Scene scene = parse_scene(runaway, "bad.toml");
  const OutputEstimate e = estimate_output(scene, 20);
  EXPECT_GT(e.snapshots, 1e8);
  EXPECT_GT(e.bytes, 1e11);
  try {
    check_output_size(scene, e, fs::temp_directory_path());
    ADD_FAILURE() << "a runaway output was accepted";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("bad.toml:"), std::string::npos) << message;
    EXPECT_NE(message.find("output.snapshot_every = 1e-09"), std::string::npos) << message;
    EXPECT_NE(message.find("more than output.max_bytes = 10 GB (the default)"), std::string::npos) << message;
  }
  const Scene allowed = parse_scene(runaway + "max_bytes = 1e15\n", "ok.toml");
  EXPECT_TRUE(allowed.output.max_bytes_given);
  EXPECT_NO_THROW(check_output_size(allowed, estimate_output(allowed, 20), fs::temp_directory_path()));
  // A file system too small for a run that the limit allows: refused too, naming the free space.
  const Scene big = parse_scene(replace(kBox, "end = 0.1", "end = 1e6") + "[output]\nsnapshot_every = 1e-6\n", "big.toml");
  const OutputEstimate huge = estimate_output(big, 20);
  Scene limitless = big;
  limitless.output.max_bytes = 1e30;  // as if the default were that large
  try {
    check_output_size(limitless, huge, fs::temp_directory_path());
    ADD_FAILURE() << "an output of " << huge.bytes << " bytes fits the disk?";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("free on the file system"), std::string::npos) << error.what();
  }
  // The ordinary scene is far below both.
  const Scene ordinary = parse_scene(kBox, "ok.toml");
  EXPECT_NO_THROW(check_output_size(ordinary, estimate_output(ordinary, 20), fs::temp_directory_path()));
  EXPECT_EQ(estimate_output(ordinary, 20).snapshots, 101);  // k * 0.001 s for k = 0..100, the last at the end
}
