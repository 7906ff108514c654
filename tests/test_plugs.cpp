// Plugs in a narrow tube (scenarios/analysis/plugs.hpp) on constructed profiles and histories
// whose answers are known exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "scenarios/analysis/plugs.hpp"

namespace carom {
namespace {

TEST(Plugs, RunsAtOrAboveTheThresholdAndLongEnough) {
  // Bins of 1 mm from z = 0.01 m. Runs >= 0.3: bins 1-2 (a plug), bin 4 (one bin: beads in
  // flight, dropped), bins 6-8 (a plug reaching the top); 0.3 itself counts as dense.
  const std::vector<double> profile{0, 0.5, 0.6, 0, 0.35, 0.1, 0.3, 0.5, 0.5};
  const std::vector<Plug> plugs = detect_plugs(profile, 0.01, 1e-3, 0.3, 2);
  ASSERT_EQ(plugs.size(), 2u);
  EXPECT_NEAR(plugs[0].lower, 0.011, 1e-15);
  EXPECT_NEAR(plugs[0].upper, 0.013, 1e-15);
  EXPECT_NEAR(plugs[1].lower, 0.016, 1e-15);
  EXPECT_NEAR(plugs[1].upper, 0.019, 1e-15);
  EXPECT_EQ(detect_plugs(profile, 0.01, 1e-3, 0.3, 1).size(), 3u);  // bin 4 counts alone
  EXPECT_EQ(detect_plugs(profile, 0.01, 1e-3, 0.7, 1).size(), 0u);
}

TEST(Plugs, AxialSolidFractionByHand) {
  // Two spheres of radius 1 mm in bin 0 and one in bin 2 of a 4 mm^2 x 5 mm column.
  const double v = 4.0 / 3.0 * M_PI * 1e-9, area = 4e-6, bin = 5e-3;
  const std::vector<double> p = axial_solid_fraction({0.001, 0.004, 0.012, 0.02},
                                                     {1e-3, 1e-3, 1e-3, 1e-3}, 0.0, bin, 3, area);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_DOUBLE_EQ(p[0], 2 * v / (area * bin));
  EXPECT_DOUBLE_EQ(p[1], 0.0);
  EXPECT_DOUBLE_EQ(p[2], v / (area * bin));  // z = 0.02 is above the last bin: not counted
}

TEST(Plugs, ConclusionsOfAPlugRisingAtAKnownSpeed) {
  // Bins of 1 mm from 0. Two plugs: a fixed one (bins 2-5) and one of 6 bins (0.5) whose top
  // bin is followed by a bin at 0.1, moving up one bin every 0.1 s from bins 10-15; samples every
  // 0.01 s for 1.5 s. With threshold 0.3 the top crosses at the last dense bin's centre plus
  // (0.5 - 0.3) / (0.5 - 0.1) = 0.5 bin, i.e. at its upper edge; over windows of 0.1 s it rises
  // by exactly 1 mm: 0.01 m/s, never falls.
  PlugGeometry g;
  g.bottom = 0;
  g.bin = 1e-3;
  g.bins = 40;
  g.area = 1e-5;
  g.diameter = 1e-3;
  g.min_bins = 2;
  g.rate_window = 0.1;
  g.thresholds = {0.3, 0.45};
  std::vector<double> times, profiles, heights;
  const std::size_t particles = 3;
  for (int r = 0; r <= 150; ++r) {
    const double t = 0.01 * r;
    times.push_back(t);
    std::vector<double> p(40, 0.0);
    for (int b = 2; b <= 5; ++b) p[b] = 0.5;
    const int first = 10 + r / 10;
    for (int b = first; b < first + 6; ++b) p[b] = 0.5;
    p[first + 6] = 0.1;
    profiles.insert(profiles.end(), p.begin(), p.end());
    // Particle 0 sits in the lower plug; particle 1 moves from the lower plug into the upper
    // one at t = 0.5 s; particle 2 rises steadily at 0.002 m/s from z = 0.
    heights.push_back(0.003);
    heights.push_back(t < 0.5 ? 0.004 : 0.0005 + 1e-3 * first);
    heights.push_back(0.002 * t);
  }
  const std::vector<PlugConclusions> c = conclude_plugs(g, times, profiles, heights, particles);
  ASSERT_EQ(c.size(), 2u);
  const PlugConclusions& x = c[0];
  EXPECT_DOUBLE_EQ(x.plugs_mean, 2.0);
  EXPECT_DOUBLE_EQ(x.plugs_std, 0.0);
  EXPECT_NEAR(x.length_mean, 5.0, 1e-12);  // lengths 4 and 6 diameters
  EXPECT_NEAR(x.length_std, 1.0, 1e-12);
  EXPECT_EQ(x.plug_count, 2u * 151u);
  EXPECT_NEAR(x.rise_speed, 0.01, 1e-12);
  EXPECT_EQ(x.fall_speed, 0.0);
  EXPECT_NEAR(x.exchange, 1.0 / 3.0, 1e-15);  // particle 1 only
  // Travel in 1 s: particles 0 and 1 (0.001 + 1 mm per 0.1 s once moved)... computed directly.
  double travel = 0;
  std::size_t pairs = 0;
  for (std::size_t r = 0; r + 100 < times.size(); ++r, pairs += particles)
    for (std::size_t i = 0; i < particles; ++i)
      travel += std::abs(heights[(r + 100) * particles + i] - heights[r * particles + i]);
  EXPECT_NEAR(x.travel, travel / static_cast<double>(pairs), 1e-15);
  // At 0.45 the top crossing moves to (0.5 - 0.45) / 0.4 = 1/8 bin above the centre: the same
  // speed, lengths unchanged (the runs are the same bins).
  EXPECT_NEAR(c[1].rise_speed, 0.01, 1e-12);
  EXPECT_NEAR(c[1].length_mean, 5.0, 1e-12);
  EXPECT_NEAR(c[1].bed_top_mean - x.bed_top_mean, (0.125 - 0.5) * 1e-3, 1e-12);
}

}  // namespace
}  // namespace carom
