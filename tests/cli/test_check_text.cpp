// `carom check` as a person reads it: numbers as typed or to 4 significant digits (never the
// float noise of 0.10000000000000001 or 2.4000000000000003e-06), lines of at most 100
// characters, and the settling run left out unless asked for (a check answers in about a
// second; settling takes as long as that much simulation).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>

#include "core/display_number.hpp"
#include "scenarios/cli/check.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {
namespace {

namespace fs = std::filesystem;

TEST(DisplayNumber, ShowsTypedValuesAsTypedAndDerivedOnesToFourDigits) {
  // As typed: a value of at most 6 significant digits comes back exactly.
  EXPECT_EQ(display_number(0.1), "0.1");
  EXPECT_EQ(display_number(1.00001), "1.00001");
  EXPECT_EQ(display_number(2e-5), "2e-05");
  EXPECT_EQ(display_number(800.0), "800");
  EXPECT_EQ(display_number(-0.25), "-0.25");
  // Derived: the noise of binary arithmetic is rounded away.
  EXPECT_EQ(display_number(0.1 + 0.2), "0.3");                        // 0.30000000000000004
  EXPECT_EQ(display_number(0.2 * 0.1 * 0.12 * 1e-3), "2.4e-06");     // 2.4000000000000003e-06
  EXPECT_EQ(display_number(1.3089969389957471e-06), "1.309e-06");
  EXPECT_EQ(display_number(7.716049382716049), "7.716");
  EXPECT_EQ(display_number(std::nan("")), "nan");
  EXPECT_EQ(display_number(-INFINITY), "-inf");
}

TEST(CheckText, LongLinesAreWrappedAtSpacesWithTheirIndent) {
  const std::string line = "  reason: " + std::string(60, 'a') + " " + std::string(60, 'b') + " c\n";
  EXPECT_EQ(wrap_lines(line, 100), "  reason: " + std::string(60, 'a') + "\n      " + std::string(60, 'b') + " c\n");
  // A word longer than the width stays whole; short lines and blank lines are untouched.
  const std::string path = "  " + std::string(120, 'p') + "\n\nshort\n";
  EXPECT_EQ(wrap_lines(path, 100), path);
}

/// The shipped scene files (sweeps and charts are not scenes: load_scene refuses them).
std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(CAROM_SCENES_DIR))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(CheckText, EveryShippedSceneReadsWithoutFloatNoiseInLinesOf100) {
  // A number of more than 6 significant digits is float noise (display_number never writes one).
  const std::regex number(R"(\d+\.\d+)");
  const auto noisy = [&](const std::string& line) {
    for (auto m = std::sregex_iterator(line.begin(), line.end(), number); m != std::sregex_iterator(); ++m) {
      const std::string digits = std::regex_replace(m->str(), std::regex(R"(^[0.]+|\.)"), "");
      if (digits.size() > 6) return true;
    }
    return false;
  };
  int checked = 0;
  for (const fs::path& file : shipped_scenes()) {
    Scene scene;
    try {
      scene = load_scene(file.string());
    } catch (const SceneError&) {
      continue;  // a sweep or chart file
    }
    std::ostringstream out;
    check_scene(std::move(scene), false, out);
    ++checked;
    std::istringstream lines(out.str());
    for (std::string line; std::getline(lines, line);) {
      if (line.size() > kCheckWidth) {
        EXPECT_EQ(line.find(' ', line.find_first_not_of(' ')), std::string::npos)
            << file.filename() << ": a line of " << line.size() << " characters: " << line;
      }
      EXPECT_FALSE(noisy(line)) << file.filename() << ": " << line;
    }
    EXPECT_NE(out.str().find("the least model this scene needs"), std::string::npos) << file.filename();
  }
  EXPECT_GE(checked, 24);
}

TEST(CheckText, SettlingIsLeftOutUnlessAskedFor) {
  // fines_bed settles for 0.2 s: check takes the bed as a settled packing and says so.
  const std::string fines = std::string(CAROM_SCENES_DIR) + "/fines_bed.toml";
  std::ostringstream quick;
  check_scene(load_scene(fines), false, quick);
  EXPECT_NE(quick.str().find("is not run by carom check (carom check --settle runs it)"), std::string::npos)
      << quick.str();
  EXPECT_NE(quick.str().find("of a settled random packing"), std::string::npos) << quick.str();
  // A scene without settling says nothing about it.
  std::ostringstream gas;
  check_scene(load_scene(std::string(CAROM_SCENES_DIR) + "/elastic_gas.toml"), false, gas);
  EXPECT_EQ(gas.str().find("settl"), std::string::npos) << gas.str();
}

TEST(CheckText, ErrorMessagesShowArraysAsTyped) {
  // An array in an error is written number by number as typed (toml++'s printer would give
  // [ 0.10000000000000001, 0.20000000000000001 ]).
  try {
    load_scene(std::string(CAROM_SCENES_DIR) + "/fines_bed.toml", {"domain.min=[0.1,0.2]"});
    FAIL() << "a two-component corner was accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("domain.min = [0.1, 0.2] is not"), std::string::npos) << message;
  }
}

TEST(CheckText, ErrorMessagesShowValuesAsTyped) {
  // An out-of-range --set value is quoted as typed, not as its binary double.
  try {
    load_scene(std::string(CAROM_SCENES_DIR) + "/fines_bed.toml", {"gas.boundaries.z_low.ramp_time=-0.1"});
    FAIL() << "a negative ramp time was accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("-0.1"), std::string::npos) << message;
    EXPECT_EQ(message.find("0.10000000000000001"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace carom
