// What a new user and a hostile input find (issue 20), checked at the scene layer: every
// mistake is refused at once, with a message that says what is wrong and what is allowed: a
// directory or a sweep file given as the scene, a negative seed, a value a sweep file set, a
// fill its region cannot hold (refused before anything is allocated), an output that would
// fill the disk.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scenarios/scene/overrides.hpp"
#include "scenarios/scene/scene.hpp"

using namespace carom;
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
