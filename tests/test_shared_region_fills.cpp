// Fills of several species into one region, bounded together before anything is placed
// (fill_capacity.hpp). Each species alone used to be checked against the region; two that fit
// alone but not together went on to the placement, which tried for a long time and failed.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "scenarios/scene/fill_capacity.hpp"
#include "scenarios/scene/scene.hpp"

using namespace carom;

namespace {

/// A 1 cm box (1e-6 m^3) with two species; FILL_A and FILL_B stand for their fills.
std::string two_species(const std::string& diameter_b, const std::string& fill_a,
                        const std::string& fill_b) {
  return "[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [0.01, 0.01, 0.01]\n"
         "[regions.lower]\nmin = [0.0, 0.0, 0.0]\nmax = [0.01, 0.01, 0.005]\n"
         "[regions.upper]\nmin = [0.0, 0.0, 0.005]\nmax = [0.01, 0.01, 0.01]\n"
         "[[species]]\nname = \"a\"\ndiameter = 1.0e-3\ndensity = 2500.0\nfill = " +
         fill_a +
         "\n"
         "[[species]]\nname = \"b\"\ndiameter = " +
         diameter_b + "\ndensity = 2500.0\nfill = " + fill_b +
         "\n"
         "[time]\nend = 0.1\n";
}

/// The SceneError of the fill checks alone (no placement); "" when they pass.
std::string capacity_error(const std::string& text) {
  try {
    const Scene scene = parse_scene(text, "fills.toml");
    check_fill_capacities(scene, fill_counts(scene));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// Two species of one diameter, 700 random beads each: 700 (pi/6) 1e-9 m^3 = 3.665e-7 m^3, 0.3665
// of the box each (below 0.64: each fits alone), 0.733 together, above random close packing.
// Refused at once (the placement would have run into its jam and failed only after seconds),
// naming both fills' keys and lines and the combined fraction.
TEST(SharedRegionFills, EqualRandomFillsAreBoundedTogether) {
  const std::string text = two_species("1.0e-3", "{ count = 700 }", "{ count = 700 }");
  const auto start = std::chrono::steady_clock::now();
  const std::string message = capacity_error(text);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_NE(message.find("fills.toml:19: the fills of region \"domain\""), std::string::npos)
      << message;
  EXPECT_NE(
      message.find("700 particles of species \"a\" (species[0].fill.count = 700 at fills.toml:14)"),
      std::string::npos)
      << message;
  EXPECT_NE(
      message.find("700 particles of species \"b\" (species[1].fill.count = 700 at fills.toml:19)"),
      std::string::npos)
      << message;
  EXPECT_NE(message.find("together 0.733 of its volume"), std::string::npos) << message;
  EXPECT_NE(message.find("random close packing"), std::string::npos) << message;
  // Each alone is accepted by the same checks: the refusal is the combination's.
  EXPECT_EQ(capacity_error(two_species("1.0e-3", "{ count = 700 }", "{ count = 1 }")), "");
  // Into different regions, each of half the box, 300 each (0.314 of its region) fit.
  EXPECT_EQ(capacity_error(two_species("1.0e-3", "{ count = 300, region = \"lower\" }",
                                       "{ count = 300, region = \"upper\" }")),
            "");
}

// One diameter with a lattice among the fills: the bound is the densest packing of equal
// spheres, pi / sqrt(18) = 0.7405. 726 + 726 beads are 0.7603 of the box: refused; 700 + 700
// (0.733) pass this check (the lattice itself then decides).
TEST(SharedRegionFills, EqualFillsWithALatticeAreBoundedByTheDensestPacking) {
  const std::string message = capacity_error(
      two_species("1.0e-3", "{ count = 726, arrangement = \"fcc\" }", "{ count = 726 }"));
  EXPECT_NE(message.find("together 0.7603 of its volume"), std::string::npos) << message;
  EXPECT_NE(message.find("pi / sqrt(18)"), std::string::npos) << message;
  EXPECT_EQ(capacity_error(
                two_species("1.0e-3", "{ count = 700, arrangement = \"fcc\" }", "{ count = 700 }")),
            "");
}

// Different diameters can pack denser than either alone, so the only sure bound is the region
// itself: 1200 beads of 1 mm (0.6283) and 8000 of 0.5 mm (0.5236) are 1.152 of the box,
// refused; with 3000 of 0.5 mm (0.8247 together) the check leaves it to the placement.
TEST(SharedRegionFills, MixedDiametersAreBoundedByTheRegionVolume) {
  const std::string message =
      capacity_error(two_species("0.5e-3", "{ count = 1200 }", "{ count = 8000 }"));
  EXPECT_NE(message.find("together 1.152 of its volume"), std::string::npos) << message;
  EXPECT_NE(message.find("never fill more than all of it"), std::string::npos) << message;
  EXPECT_EQ(capacity_error(two_species("0.5e-3", "{ count = 1200 }", "{ count = 3000 }")), "");
}
