// Polygon walls in scenes: the [[walls]] type = "polygon" key `vertices` and its errors (file,
// line, key, value, allowed range).
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "scenarios/scene/scene.hpp"

using namespace carom;

namespace {

/// A square plate tilted 30 degrees in a walled box. Line numbers: [domain] is line 1.
const std::string kPlate =
    "[domain]\n"                                 // 1
    "min = [-0.05, -0.05, 0.0]\n"                // 2
    "max = [0.05, 0.05, 0.1]\n"                  // 3
    "gravity = [0.0, 0.0, -9.81]\n"              // 4
    "[[species]]\n"                              // 5
    "name = \"bead\"\n"                          // 6
    "diameter = 2.0e-3\n"                        // 7
    "density = 2500.0\n"                         // 8
    "fill = { count = 10, region = \"top\" }\n"  // 9
    "[regions.top]\n"                            // 10
    "min = [-0.01, -0.01, 0.08]\n"               // 11
    "max = [0.01, 0.01, 0.095]\n"                // 12
    "[[walls]]\n"                                // 13
    "name = \"plate\"\n"                         // 14
    "type = \"polygon\"\n"                       // 15
    "vertices = [[-0.03, -0.026, 0.035], [0.03, -0.026, 0.035], [0.03, 0.026, 0.065], "
    "[-0.03, 0.026, 0.065]]\n"  // 16
    "[time]\n"                  // 17
    "end = 0.1\n";              // 18

const std::string kVertices =
    "vertices = [[-0.03, -0.026, 0.035], [0.03, -0.026, 0.035], [0.03, 0.026, 0.065], "
    "[-0.03, 0.026, 0.065]]\n";

std::string with_vertices(const std::string& list) {
  std::string text = kPlate;
  const auto at = text.find(kVertices);
  EXPECT_NE(at, std::string::npos);
  return text.replace(at, kVertices.size(), "vertices = " + list + "\n");
}

std::string error_of(const std::string& text) {
  try {
    Scene scene = parse_scene(text, "bad.toml");
    build_initial_state(scene);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, const std::vector<std::string>& fragments) {
  const std::string message = error_of(text);
  ASSERT_FALSE(message.empty()) << "accepted:\n" << text;
  for (const auto& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

}  // namespace

TEST(PolygonScene, ReadsThePolygon) {
  Scene scene = parse_scene(kPlate, "plate.toml");
  ASSERT_EQ(scene.system.walls.size(), 7u);  // six box walls and the plate
  const Wall& wall = scene.system.walls.back();
  EXPECT_EQ(wall.name, "plate");
  const PolygonWall& plate = std::get<PolygonWall>(wall.shape);
  EXPECT_EQ(plate.vertices().size(), 4u);
  EXPECT_NEAR(plate.area(), 0.06 * std::hypot(0.052, 0.03), 1e-15);
  EXPECT_NE(wall.description().find("polygon of 4 vertices"), std::string::npos);
  EXPECT_EQ(error_of(kPlate), "");
}

// Every message names the file, the line of the value, the dotted key and what is allowed.
TEST(PolygonScene, ErrorsNameFileLineKeyAndRange) {
  const std::string allowed = "allowed: at least 3 distinct points";
  expect_error(with_vertices("[[0, 0, 0.05], [0.01, 0, 0.05]]"),
               {"bad.toml:16", "walls[0].vertices = ", "has 2 points; at least 3"});
  expect_error(with_vertices("[[0, 0, 0.05], [0.01, 0, 0.05], [0.01, 0, 0.05], [0, 0.01, 0.05]]"),
               {"bad.toml:16", "walls[0].vertices", "vertices 2 and 3 coincide", allowed});
  expect_error(with_vertices("[[0, 0, 0.05], [0.01, 0, 0.05], [0.02, 0, 0.05]]"),
               {"bad.toml:16", "walls[0].vertices", "no area", allowed});
  expect_error(
      with_vertices("[[0, 0, 0.05], [0.01, 0, 0.05], [0.01, 0.01, 0.051], [0, 0.01, 0.05]]"),
      {"bad.toml:16", "walls[0].vertices", "is not flat", "off the polygon's best plane", allowed,
       "within 1e-6 of its size"});
  expect_error(
      with_vertices("[[0, 0, 0.05], [0.01, 0, 0.05], [0.005, 0.002, 0.05], [0.01, 0.01, 0.05], "
                    "[0, 0.01, 0.05]]"),
      {"bad.toml:16", "walls[0].vertices", "not convex", "vertex 3", allowed});
  expect_error(with_vertices("[[0, 0, 0.05], [0.01, 0, 0.05], [0, 0.01]]"),
               {"bad.toml:16", "walls[0].vertices", "point 3 that is not three numbers"});
  expect_error(with_vertices("[0, 0, 0.05]"), {"bad.toml:16", "walls[0].vertices", "point 1"});
  expect_error(with_vertices("\"square\""),
               {"bad.toml:16", "walls[0].vertices", "is not an array of at least 3 points"});
  {
    std::string missing = kPlate;
    missing.replace(missing.find(kVertices), kVertices.size(), "");
    expect_error(missing, {"bad.toml", "walls[0].vertices", "is missing"});
  }
  // A periodic axis: only strips across the period.
  std::string periodic = kPlate;
  periodic.replace(periodic.find("gravity"), 0, "periodic = [\"x\"]\n");
  expect_error(periodic, {"bad.toml:17", "walls[0].vertices", "x is periodic", "strip"});
}

// A strip across a periodic axis is accepted.
TEST(PolygonScene, StripAcrossAPeriodicAxis) {
  std::string strip = with_vertices(
      "[[-0.05, -0.02, 0.03], [0.05, -0.02, 0.03], [0.05, 0.02, 0.06], [-0.05, 0.02, 0.06]]");
  strip.insert(strip.find("gravity"), "periodic = [\"x\"]\n");
  EXPECT_EQ(error_of(strip), "");
}
