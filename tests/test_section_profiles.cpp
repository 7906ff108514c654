// Profiles across sections (scenarios/analysis/section_profiles.hpp): the binned sums against a
// brute-force oracle that tests each bin's box separately, hand-computed means and spreads, and
// the averaging window.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scenarios/analysis/section_profiles.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using carom::test::kPi;

ProfileGeometry duct() {
  ProfileGeometry g;
  g.heights = {0.2, 0.5, 0.55};  // the last two overlap: a particle may count in both
  g.thickness = 0.1;
  g.vertical = 2;
  g.axis = 0;
  g.bins = 7;
  g.lower = -0.1;
  g.upper = 0.25;
  g.depth = 0.04;
  return g;
}

// The oracle: for every section and bin, the particles whose centre lies in that bin's box,
// summed directly.
std::vector<double> brute_force(const ProfileGeometry& g, const std::vector<Vec3>& r,
                                const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                                const std::vector<double>& a) {
  std::vector<double> row;
  const double width = (g.upper - g.lower) / g.bins;
  for (double h : g.heights)
    for (int b = 0; b < g.bins; ++b) {
      std::vector<double> bin(11, 0.0);
      const double left = g.lower + b * width, right = b + 1 == g.bins ? g.upper : left + width;
      for (std::size_t i = 0; i < r.size(); ++i) {
        if (r[i].x() < left || r[i].x() >= right) continue;
        if (r[i].z() < h - g.thickness / 2 || r[i].z() >= h + g.thickness / 2) continue;
        bin[0] += 1;
        bin[1] += 4.0 / 3.0 * kPi * a[i] * a[i] * a[i];
        for (int c = 0; c < 3; ++c) {
          bin[2 + c] += v[i][c];
          bin[5 + c] += v[i][c] * v[i][c];
          bin[8 + c] += w[i][c];
        }
      }
      row.insert(row.end(), bin.begin(), bin.end());
    }
  return row;
}

TEST(SectionProfiles, SumsEqualABruteForceBinning) {
  const ProfileGeometry g = duct();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(-0.15, 0.3), z(0.0, 0.7), u(-2.0, 2.0), s(1e-3, 3e-3);
  std::vector<Vec3> r, v, w;
  std::vector<double> a;
  for (int i = 0; i < 5000; ++i) {
    r.emplace_back(x(rng), x(rng), z(rng));
    v.emplace_back(u(rng), u(rng), u(rng));
    w.emplace_back(u(rng), u(rng), u(rng));
    a.push_back(s(rng));
  }
  const std::vector<double> fast = profile_sums(g, r, v, w, a), slow = brute_force(g, r, v, w, a);
  ASSERT_EQ(fast.size(), g.row_width());
  ASSERT_EQ(fast.size(), slow.size());
  // The same sums in the same order of particles: equal to the last bit, but for bins where
  // floor((x - lower) / width) and the oracle's edge comparisons disagree (x within a rounding
  // error of an edge: none among these 5000).
  for (std::size_t j = 0; j < fast.size(); ++j) EXPECT_EQ(fast[j], slow[j]) << "value " << j;
  double counted = 0;
  for (std::size_t j = 0; j < fast.size(); j += 11) counted += fast[j];
  EXPECT_GT(counted, 1000.0);  // the test sees many particles in bins
}

TEST(SectionProfiles, MeansSpreadsAndSolidFractionByHand) {
  ProfileGeometry g;
  g.heights = {1.0};
  g.thickness = 0.2;
  g.bins = 2;
  g.lower = 0.0;
  g.upper = 1.0;
  g.depth = 0.5;
  const double radius = 0.01;
  // Sample 1: two particles in bin 0 (velocities (1, 0, 2) and (3, 0, -2)); sample 2: one
  // particle in bin 0 with (2, 0, 0), one in bin 1, one outside the section (z = 1.2).
  const std::vector<double> one =
      profile_sums(g, {{0.1, 0, 1.0}, {0.4, 0, 0.95}}, {{1, 0, 2}, {3, 0, -2}},
                   {{0, 5, 0}, {0, 1, 0}}, {radius, radius});
  const std::vector<double> two = profile_sums(
      g, {{0.2, 0, 1.05}, {0.7, 0, 1.0}, {0.3, 0, 1.2}}, {{2, 0, 0}, {0, -1, 0}, {9, 9, 9}},
      {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, {radius, radius, radius});
  std::vector<double> sums = one;
  sums.insert(sums.end(), two.begin(), two.end());
  const ProfileConclusions c = conclude_profiles(g, {0.0, 1.0}, sums);
  ASSERT_EQ(c.samples, 2u);
  ASSERT_EQ(c.sections.size(), 1u);
  const SectionProfile& s = c.sections[0];
  // Bin 0: velocities x {1, 3, 2}: mean 2, population spread sqrt(2/3); z {2, -2, 0}: mean 0,
  // spread sqrt(8/3); spin y {5, 1, 0}: mean 2. Three particle volumes over two samples of a
  // bin of 0.2 x 0.5 x 0.5 m^3.
  const double volume = 4.0 / 3.0 * kPi * radius * radius * radius;
  EXPECT_DOUBLE_EQ(s.particles[0], 1.5);
  EXPECT_DOUBLE_EQ(s.solid_fraction[0], 3 * volume / (2 * 0.05));
  EXPECT_DOUBLE_EQ(s.mean_velocity[0].x(), 2.0);
  EXPECT_NEAR(s.std_velocity[0].x(), std::sqrt(2.0 / 3.0), 1e-15);
  EXPECT_NEAR(s.mean_velocity[0].z(), 0.0, 1e-15);
  EXPECT_NEAR(s.std_velocity[0].z(), std::sqrt(8.0 / 3.0), 1e-15);
  EXPECT_DOUBLE_EQ(s.mean_spin[0].y(), 2.0);
  // Bin 1: one particle, no spread.
  EXPECT_DOUBLE_EQ(s.particles[1], 0.5);
  EXPECT_DOUBLE_EQ(s.mean_velocity[1].y(), -1.0);
  EXPECT_DOUBLE_EQ(s.std_velocity[1].y(), 0.0);

  // A window from t = 0.5 keeps the second sample only.
  g.start = 0.5;
  const ProfileConclusions late = conclude_profiles(g, {0.0, 1.0}, sums);
  EXPECT_EQ(late.samples, 1u);
  EXPECT_DOUBLE_EQ(late.first, 1.0);
  EXPECT_DOUBLE_EQ(late.sections[0].mean_velocity[0].x(), 2.0);
  EXPECT_DOUBLE_EQ(late.sections[0].std_velocity[0].x(), 0.0);
  // A window after every sample averages nothing: NaN, not zero.
  g.start = 2.0;
  const ProfileConclusions none = conclude_profiles(g, {0.0, 1.0}, sums);
  EXPECT_EQ(none.samples, 0u);
  EXPECT_TRUE(std::isnan(none.sections[0].solid_fraction[0]));
  EXPECT_TRUE(std::isnan(none.sections[0].mean_velocity[0].x()));
}

TEST(SectionProfiles, RefusesInputsOfDifferentLengths) {
  const ProfileGeometry g = duct();
  EXPECT_THROW(profile_sums(g, {{0, 0, 0}}, {}, {{0, 0, 0}}, {1e-3}), std::invalid_argument);
  EXPECT_THROW(conclude_profiles(g, {0.0, 1.0}, std::vector<double>(g.row_width())),
               std::invalid_argument);
}

}  // namespace
}  // namespace carom
