// The statistics of `carom chart` on constructed data: mean and standard error over seeds, the
// error against the reference and its uncertainty (the relative one against a Monte Carlo
// oracle), the Pareto front (a known front, ties, points dominated only within noise, and a
// sort-and-sweep second implementation on random points with many ties), and the cheapest
// variant within a tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "core/rng.hpp"
#include "scenarios/chart/chart_stats.hpp"

namespace carom {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------------------------
// Seeds: mean and standard error, worked by hand.

TEST(ChartStatistics, MeanAndStandardErrorByHand) {
  // {1, 2, 3, 4}: mean 2.5, sample variance (2.25 + 0.25 + 0.25 + 2.25) / 3 = 5/3,
  // standard error sqrt(5/3 / 4) = 0.6454972243679028.
  const SeedStatistics s = seed_statistics({1.0, 2.0, 3.0, 4.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.standard_error, 0.6454972243679028, 1e-15);
}

TEST(ChartStatistics, MissingValuesAreLeftOut) {
  const SeedStatistics s = seed_statistics({kNaN, 1.0, 3.0, kNaN});
  EXPECT_EQ(s.count, 2u);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_NEAR(s.standard_error, 1.0, 1e-15);  // sd sqrt(2), over sqrt(2)
  const SeedStatistics one = seed_statistics({5.0});
  EXPECT_EQ(one.count, 1u);
  EXPECT_DOUBLE_EQ(one.mean, 5.0);
  EXPECT_TRUE(std::isnan(one.standard_error));
  const SeedStatistics none = seed_statistics({kNaN});
  EXPECT_EQ(none.count, 0u);
  EXPECT_TRUE(std::isnan(none.mean));
}

// ---------------------------------------------------------------------------------------------
// Errors against the reference.

TEST(ChartStatistics, AbsoluteErrorCombinesStandardErrors) {
  const SeedStatistics reference{3, 10.0, 0.4}, variant{3, 11.0, 0.3};
  const ErrorEstimate e =
      error_against_reference(variant, reference, ErrorMeasure::Absolute, false);
  EXPECT_DOUBLE_EQ(e.error, 1.0);
  EXPECT_NEAR(e.uncertainty, 0.5, 1e-15);  // sqrt(0.3^2 + 0.4^2)
  EXPECT_DOUBLE_EQ(e.noise, 0.3);
  EXPECT_FALSE(e.within_noise);  // 1.0 > 0.5
  const SeedStatistics close{3, 9.6, 0.3};
  const ErrorEstimate n = error_against_reference(close, reference, ErrorMeasure::Absolute, false);
  EXPECT_NEAR(n.error, -0.4, 1e-14);
  EXPECT_TRUE(n.within_noise);  // 0.4 < 0.5
}

TEST(ChartStatistics, RelativeErrorByHand) {
  // E = 11/10 - 1 = 0.1; u = sqrt(0.3^2 + 1.1^2 0.4^2) / 10 = sqrt(0.2836) / 10.
  const SeedStatistics reference{3, 10.0, 0.4}, variant{3, 11.0, 0.3};
  const ErrorEstimate e =
      error_against_reference(variant, reference, ErrorMeasure::Relative, false);
  EXPECT_NEAR(e.error, 0.1, 1e-15);
  EXPECT_NEAR(e.uncertainty, std::sqrt(0.2836) / 10, 1e-15);
  EXPECT_NEAR(e.noise, 0.03, 1e-15);
  // Negative means: m_v / m_r - 1 still says "10 % larger in magnitude"; the noise is over |m_r|.
  const ErrorEstimate neg =
      error_against_reference({3, -11.0, 0.3}, {3, -10.0, 0.4}, ErrorMeasure::Relative, false);
  EXPECT_NEAR(neg.error, 0.1, 1e-15);
  EXPECT_NEAR(neg.noise, 0.03, 1e-15);
}

TEST(ChartStatistics, RelativeUncertaintyAgreesWithSampling) {
  // Oracle: draw the two means from normal distributions with the given standard errors and
  // take the standard deviation of m_v / m_r - 1. The first-order formula misses terms of
  // relative size (s_r / m_r)^2 = 0.0016 here; 400000 draws estimate a standard deviation to
  // 1 / sqrt(2 * 400000) = 0.11 %, so 1 % is a safe, still sharp tolerance.
  const SeedStatistics reference{4, 10.0, 0.4}, variant{4, 11.0, 0.3};
  const ErrorEstimate e =
      error_against_reference(variant, reference, ErrorMeasure::Relative, false);
  Rng rng(2024);
  const int draws = 400000;
  double sum = 0, squares = 0;
  for (int k = 0; k < draws; ++k) {
    const double r = (11.0 + 0.3 * rng.normal()) / (10.0 + 0.4 * rng.normal()) - 1;
    sum += r;
    squares += r * r;
  }
  const double mean = sum / draws;
  const double sd = std::sqrt(squares / draws - mean * mean);
  EXPECT_NEAR(e.uncertainty / sd, 1.0, 0.01);
}

TEST(ChartStatistics, TheReferenceAgainstItself) {
  const SeedStatistics reference{3, 10.0, 0.4};
  const ErrorEstimate e =
      error_against_reference(reference, reference, ErrorMeasure::Relative, true);
  EXPECT_EQ(e.error, 0.0);
  EXPECT_NEAR(e.uncertainty, 0.04, 1e-15);  // its own noise, not sqrt(2) times it
  EXPECT_TRUE(e.within_noise);
  const ErrorEstimate missing =
      error_against_reference({0, kNaN, kNaN}, {0, kNaN, kNaN}, ErrorMeasure::Absolute, true);
  EXPECT_TRUE(std::isnan(missing.error));
  EXPECT_FALSE(missing.within_noise);
}

TEST(ChartStatistics, UnknownStandardErrorIsNeverNoise) {
  const ErrorEstimate e =
      error_against_reference({1, 10.001, kNaN}, {3, 10.0, 0.4}, ErrorMeasure::Absolute, false);
  EXPECT_TRUE(std::isnan(e.uncertainty));
  EXPECT_FALSE(e.within_noise);
}

// ---------------------------------------------------------------------------------------------
// Pareto front.

std::vector<bool> on_front(const std::vector<ChartPoint>& points) {
  std::vector<bool> out;
  for (const FrontMembership& m : pareto_front(points)) out.push_back(m.on_front);
  return out;
}

TEST(ChartFront, KnownFront) {
  // Cost 0.5 .. 4; (3, 0.3) is dominated by (2, 0.2), (5, 0.5) by everything cheaper and better,
  // the rest trade cost for error.
  const std::vector<ChartPoint> points = {{2.0, 0.2, 0},  {0.5, 1.0, 0}, {3.0, 0.3, 0},
                                          {4.0, 0.05, 0}, {1.0, 0.5, 0}, {5.0, 0.5, 0}};
  EXPECT_EQ(on_front(points), (std::vector<bool>{true, true, false, true, true, false}));
}

TEST(ChartFront, Ties) {
  // Two identical points: neither dominates the other. Equal cost, larger error: dominated.
  // Equal error, larger cost: dominated.
  const std::vector<ChartPoint> points = {
      {1.0, 0.5, 0}, {1.0, 0.5, 0}, {1.0, 0.6, 0}, {1.5, 0.5, 0}, {2.0, 0.1, 0}};
  EXPECT_EQ(on_front(points), (std::vector<bool>{true, true, false, false, true}));
}

TEST(ChartFront, DominatedOnlyWithinNoise) {
  const std::vector<ChartPoint> points = {
      {2.0, 0.20, 0.02},   // on the front
      {3.0, 0.21, 0.02},   // dominated by 0, by 0.01 < sqrt(2) 0.02: within noise
      {3.0, 0.30, 0.02},   // dominated by 0 by 0.10: clearly
      {2.5, 0.25, 0.001},  // dominated by 0 by 0.05 > 0.02: clearly
      {4.0, 0.229, 0.02},  // within the noise of 1, but 0.029 > 0.0283 above 0: clearly
      {6.0, 0.215, kNaN},  // an unknown noise claims nothing: clearly dominated
      {0.5, 1.0, 0.02},    // on the front
  };
  const std::vector<FrontMembership> m = pareto_front(points);
  EXPECT_TRUE(m[0].on_front);
  EXPECT_FALSE(m[0].dominated_within_noise);
  EXPECT_FALSE(m[1].on_front);
  EXPECT_TRUE(m[1].dominated_within_noise);
  EXPECT_FALSE(m[2].dominated_within_noise);
  EXPECT_FALSE(m[3].dominated_within_noise);
  EXPECT_FALSE(m[4].on_front);
  EXPECT_FALSE(m[4].dominated_within_noise);
  EXPECT_FALSE(m[5].on_front);
  EXPECT_FALSE(m[5].dominated_within_noise);
  EXPECT_TRUE(m[6].on_front);
}

TEST(ChartFront, WithinNoiseOfOneButClearlyBelowAnother) {
  // Point 2 is within the noise of point 1 but clearly worse than point 0: it is off the front.
  const std::vector<ChartPoint> points = {{1.0, 0.10, 0.001}, {2.0, 0.30, 0.05}, {3.0, 0.32, 0.05}};
  const std::vector<FrontMembership> m = pareto_front(points);
  EXPECT_FALSE(m[2].on_front);
  EXPECT_FALSE(m[2].dominated_within_noise);
  EXPECT_FALSE(m[1].dominated_within_noise);  // 0.2 above point 0, noise 0.05
}

TEST(ChartFront, MissingPointsTakeNoPart) {
  const std::vector<ChartPoint> points = {{kNaN, 0.0, 0}, {1.0, kNaN, 0}, {2.0, 0.5, 0}};
  EXPECT_EQ(on_front(points), (std::vector<bool>{false, false, true}));
}

/// Second implementation: sort by cost (then error), sweep keeping the least error seen; a
/// point is on the front when its error is below every cheaper point's, or it equals the
/// previous front point exactly.
std::vector<bool> front_by_sweep(const std::vector<ChartPoint>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a].cost != points[b].cost ? points[a].cost < points[b].cost
                                            : points[a].error < points[b].error;
  });
  std::vector<bool> out(points.size(), false);
  double best = std::numeric_limits<double>::infinity();
  const ChartPoint* last = nullptr;
  for (const std::size_t k : order) {
    const ChartPoint& p = points[k];
    if (p.error < best) {
      out[k] = true;
      best = p.error;
      last = &p;
    } else if (last != nullptr && p.cost == last->cost && p.error == last->error) {
      out[k] = true;
    }
  }
  return out;
}

TEST(ChartFront, AgreesWithSortAndSweepOnRandomPointsWithTies) {
  Rng rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(rng.uniform() * 12);
    std::vector<ChartPoint> points;
    for (std::size_t k = 0; k < n; ++k)  // a 5 x 5 grid of values: many ties
      points.push_back({std::floor(rng.uniform() * 5), std::floor(rng.uniform() * 5), 0.1});
    ASSERT_EQ(on_front(points), front_by_sweep(points)) << "trial " << trial;
  }
}

// ---------------------------------------------------------------------------------------------
// Cheapest within a tolerance.

TEST(ChartCheapest, PicksTheCheapestAcceptableOtherThanTheReference) {
  const std::vector<ChartPoint> points = {
      {10.0, 0.0, 0},   // 0: the reference (cheapest would be wrong: it is excluded)
      {0.1, 0.30, 0},   // 1: too inaccurate
      {0.5, 0.05, 0},   // 2: acceptable
      {0.5, 0.02, 0},   // 3: acceptable, same cost, smaller error: wins the tie
      {2.0, 0.001, 0},  // 4: acceptable but dearer
  };
  EXPECT_EQ(cheapest_within(points, 0.05, 0), std::optional<std::size_t>(3));
  EXPECT_EQ(cheapest_within(points, 0.3, 0), std::optional<std::size_t>(1));  // boundary counts
  EXPECT_EQ(cheapest_within(points, 0.0001, 0), std::nullopt);
  std::vector<ChartPoint> cheap_reference = points;
  cheap_reference[0].cost = 0.01;
  EXPECT_EQ(cheapest_within(cheap_reference, 0.05, 0), std::optional<std::size_t>(3));
  EXPECT_EQ(cheapest_within({{1.0, kNaN, 0}, {kNaN, 0.0, 0}}, 1.0, 5), std::nullopt);
}

}  // namespace
}  // namespace carom
