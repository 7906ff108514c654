// Mixing estimators on constructed data: the sample grid they bin into, the Lacey index
// (segregated -> 0, random -> 1), the mixing-rate fit, and the height segregation indices.
// Every random input comes from a seeded carom::Rng.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/rng.hpp"
#include "scenarios/analysis/mixing.hpp"
#include "analysis_support.hpp"
#include "scenarios/analysis/sample_grid.hpp"

namespace carom {
namespace {

using test::unit_cube_grid;

std::vector<Vec3> uniform_points(std::size_t count, Rng& rng) {
  std::vector<Vec3> points(count);
  for (Vec3& p : points) p = Vec3(rng.uniform(), rng.uniform(), rng.uniform());
  return points;
}

using test::Spread;
using test::spread_of;

// ---------------------------------------------------------------------------------------------
// Sample grid: flat index order, closed upper face, outside points. Exact integer answers.

TEST(SampleGrid, CellIndexAndVolume) {
  SampleGrid grid;
  grid.lower = Vec3(-1.0, 0.0, 2.0);
  grid.upper = Vec3(1.0, 3.0, 4.0);
  grid.cells = {2, 3, 4};
  EXPECT_EQ(grid.size(), 24u);
  EXPECT_NEAR(grid.cell_volume(), 12.0 / 24.0, 1e-15);
  EXPECT_EQ(grid.cell_of(Vec3(-1.0, 0.0, 2.0)), 0);
  EXPECT_EQ(grid.cell_of(Vec3(0.5, 1.5, 2.1)), 1 + 2 * 1);
  EXPECT_EQ(grid.cell_of(Vec3(-0.5, 0.5, 3.6)), 0 + 2 * (0 + 3 * 3));
  EXPECT_EQ(grid.cell_of(Vec3(1.0, 3.0, 4.0)), 23) << "the upper face belongs to the last cell";
  EXPECT_EQ(grid.cell_of(Vec3(1.0 + 1e-12, 1.0, 3.0)), -1);
  EXPECT_EQ(grid.cell_of(Vec3(0.0, -1e-12, 3.0)), -1);
  EXPECT_EQ(grid.cell_of(Vec3(0.0, std::nan(""), 3.0)), -1);
  EXPECT_EQ(grid.cell_of(grid.cell_centre(17)), 17);
  grid.cells[1] = 0;
  EXPECT_THROW(grid.check(), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Lacey index

// Tagged particles exactly in the lower half, and a grid with a cell boundary at mid-height:
// every cell is pure, so s^2 = s0^2 and M = 0; only round-off in the sums remains (1e-12).
TEST(LaceyIndex, FullySegregatedIsZero) {
  Rng rng(11);
  const std::vector<Vec3> positions = uniform_points(4000, rng);
  std::vector<char> tagged(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) tagged[i] = positions[i].z() < 0.5;
  const LaceyIndex lacey = lacey_index(positions, tagged, unit_cube_grid(4, 4, 4));
  EXPECT_NEAR(lacey.index, 0.0, 1e-12);
  EXPECT_NEAR(lacey.variance, lacey.segregated_variance, 1e-12);
  EXPECT_EQ(lacey.cells_used, 64u);
}

// Tags drawn independently with P = 0.3 over 2000 uniform particles in 64 cells, 400 times.
// lacey_index's n = (N-1)/(K-1) makes E[M] = 1 exactly (derivation in mixing.hpp), so the mean
// over the repetitions must lie within 3 standard errors of 1 (a 0.3 % chance to fail by bad
// luck, fixed by the seed). The spread itself is checked against the chi-square picture:
// N s^2/(P(1-P)) ~ chi^2 with K-1 degrees of freedom gives sd(M) = sqrt(2 (K-1))/(N - K);
// 400 repetitions estimate an sd to 1/sqrt(800) = 3.5 %, so 15 % is over 4 of those plus the
// small non-Gaussian (finite n ~ 31) corrections.
TEST(LaceyIndex, RandomMixtureAveragesToOne) {
  Rng rng(12);
  const std::size_t particles = 2000, repetitions = 400;
  const SampleGrid grid = unit_cube_grid(4, 4, 4);
  std::vector<double> indices;
  for (std::size_t r = 0; r < repetitions; ++r) {
    const std::vector<Vec3> positions = uniform_points(particles, rng);
    std::vector<char> tagged(particles);
    for (char& t : tagged) t = rng.uniform() < 0.3;
    const LaceyIndex lacey = lacey_index(positions, tagged, grid);
    ASSERT_EQ(lacey.cells_used, 64u);
    indices.push_back(lacey.index);
  }
  const Spread m = spread_of(indices);
  const double standard_error = m.deviation / std::sqrt(double(repetitions));
  std::printf("random mixture: mean M = %.6f +- %.6f, sd %.5f\n", m.mean, standard_error,
              m.deviation);
  EXPECT_NEAR(m.mean, 1.0, 3.0 * standard_error);
  const double expected_deviation = std::sqrt(2.0 * 63.0) / (2000.0 - 64.0);
  EXPECT_NEAR(m.deviation / expected_deviation, 1.0, 0.15);
}

// Two cells of 10 particles, 8 and 2 tagged, and a sparse third cell that must be skipped.
// By hand: P = 0.5, s^2 = (10 * 0.3^2 + 10 * 0.3^2)/20 = 0.09, s0^2 = 0.25, n = 19/1,
// M = (0.25 - 0.09)/(0.25 - 0.25/19) = 0.16 * 19/4.5 = 0.675555...; exact up to round-off.
TEST(LaceyIndex, HalfMixedByHand) {
  std::vector<Vec3> positions;
  std::vector<char> tagged;
  for (int i = 0; i < 10; ++i) positions.emplace_back(0.1, 0.5, 0.25), tagged.push_back(i < 8);
  for (int i = 0; i < 10; ++i) positions.emplace_back(0.2, 0.5, 0.75), tagged.push_back(i < 2);
  for (int i = 0; i < 4; ++i) positions.emplace_back(0.8, 0.5, 0.75), tagged.push_back(1);
  positions.emplace_back(2.0, 0.5, 0.5), tagged.push_back(1);  // outside the grid
  const LaceyIndex lacey = lacey_index(positions, tagged, unit_cube_grid(2, 1, 2), 5);
  EXPECT_EQ(lacey.cells_used, 2u);
  EXPECT_NEAR(lacey.tagged_fraction, 0.5, 1e-15);
  EXPECT_NEAR(lacey.variance, 0.09, 1e-15);
  EXPECT_NEAR(lacey.particles_per_cell, 19.0, 1e-15);
  EXPECT_NEAR(lacey.index, 0.16 * 19.0 / 4.5, 1e-14);
}

// Undefined cases are NaN, not a number that looks like a result.
TEST(LaceyIndex, DegenerateInputsAreNaN) {
  Rng rng(13);
  const std::vector<Vec3> positions = uniform_points(500, rng);
  const SampleGrid grid = unit_cube_grid(2, 2, 2);
  EXPECT_TRUE(std::isnan(lacey_index(positions, std::vector<char>(500, 0), grid).index));
  EXPECT_TRUE(std::isnan(lacey_index(positions, std::vector<char>(500, 1), grid).index));
  EXPECT_TRUE(std::isnan(lacey_index({}, {}, grid).index));
  std::vector<char> half(500);
  for (std::size_t i = 0; i < half.size(); ++i) half[i] = i % 2;
  EXPECT_TRUE(std::isnan(lacey_index(positions, half, unit_cube_grid(1, 1, 1)).index))
      << "one cell: no variance between cells";
  EXPECT_TRUE(std::isnan(lacey_index(positions, half, grid, 1000).index))
      << "every cell too sparse";
  EXPECT_THROW(lacey_index(positions, std::vector<char>(3, 0), grid), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Mixing rate

// Exact data M = 1 - exp(-k t), given out of order and with a NaN sample: the normal equation
// is solved by bisection to round-off, so k comes back to 1e-10. time_to_08_data interpolates
// a concave curve linearly, so it lies after ln5/k by at most h^2 k e^{k h}/8 (h the spacing).
TEST(MixingRate, ExactCurveRecoversRate) {
  const double k = 2.5, h = 0.05;
  std::vector<double> times, lacey;
  for (int i = 40; i >= 0; --i) times.push_back(h * i), lacey.push_back(1.0 - std::exp(-k * h * i));
  lacey[7] = std::numeric_limits<double>::quiet_NaN();
  const MixingRate fit = fit_mixing_rate(times, lacey);
  ASSERT_TRUE(fit.valid);
  EXPECT_EQ(fit.points, 40u);
  EXPECT_NEAR(fit.rate / k, 1.0, 1e-10);
  EXPECT_NEAR(fit.time_to_08_fit, std::log(5.0) / k, 1e-10);
  EXPECT_LT(fit.rms_residual, 1e-12);
  EXPECT_GE(fit.time_to_08_data, std::log(5.0) / k - 1e-12);
  EXPECT_LE(fit.time_to_08_data, std::log(5.0) / k + h * h * k * std::exp(k * h) / 8.0);
}

// A bed whose sample cells do not split it at its median starts at M(0) = 0.15, not 0 (the main
// job's does). On exact data M = 1 - (1 - M0) exp(-k t) the fit from the measured start gives k
// and the time to 0.8, ln((1 - M0)/0.2)/k, to 1e-10; the old fit through M(0) = 0 is bent by
// the start it cannot meet (here k 20 % high, rms residual 0.048), which is why the run
// analysis passes M0.
TEST(MixingRate, FitStartsFromTheMeasuredStart) {
  const double k = 1.2, start = 0.15, h = 0.05;
  std::vector<double> times, lacey;
  for (int i = 0; i <= 40; ++i)
    times.push_back(h * i), lacey.push_back(1.0 - (1.0 - start) * std::exp(-k * h * i));
  const MixingRate fit = fit_mixing_rate(times, lacey, start);
  ASSERT_TRUE(fit.valid);
  EXPECT_EQ(fit.start, start);
  EXPECT_NEAR(fit.rate / k, 1.0, 1e-10);
  EXPECT_NEAR(fit.time_to_08_fit, std::log((1.0 - start) / 0.2) / k, 1e-10);
  EXPECT_LT(fit.rms_residual, 1e-12);
  const MixingRate forced = fit_mixing_rate(times, lacey);
  EXPECT_EQ(forced.start, 0.0);
  EXPECT_NEAR(forced.rate / k, 1.198, 0.002) << "the forced fit's bias (numpy grid search: 1.1982)";
  EXPECT_NEAR(forced.rms_residual, 0.0475, 0.0005);
  // A start at or above 0.8 leaves nothing to fit.
  EXPECT_FALSE(fit_mixing_rate(times, lacey, 0.85).valid);
}

// Gaussian noise sigma = 0.02 on 60 samples (values above 1 included), 200 repetitions. Least
// squares is unbiased to O(sigma^2) and its spread is the Cramer-Rao value
// sd(k) = sigma / sqrt(sum_i (t_i exp(-k t_i))^2). Mean within 3 standard errors of k; the sd
// within 20 % of the prediction (200 repetitions estimate an sd to 5 %).
TEST(MixingRate, NoisyCurveRecoversRateWithinSpread) {
  const double k = 2.0, sigma = 0.02;
  std::vector<double> times;
  double information = 0.0;
  for (int i = 1; i <= 60; ++i) {
    times.push_back(0.05 * i);
    information += std::pow(times.back() * std::exp(-k * times.back()), 2) / (sigma * sigma);
  }
  Rng rng(21);
  std::vector<double> rates;
  int above_one = 0;
  for (int r = 0; r < 200; ++r) {
    std::vector<double> lacey;
    for (double t : times) lacey.push_back(1.0 - std::exp(-k * t) + sigma * rng.normal());
    for (double m : lacey) above_one += m > 1.0;
    const MixingRate fit = fit_mixing_rate(times, lacey);
    ASSERT_TRUE(fit.valid);
    rates.push_back(fit.rate);
  }
  const Spread s = spread_of(rates);
  const double predicted = 1.0 / std::sqrt(information);
  std::printf("noisy fit: k = %.5f +- %.5f, sd %.5f (Cramer-Rao %.5f), %d samples above 1\n",
              s.mean, s.deviation / std::sqrt(200.0), s.deviation, predicted, above_one);
  EXPECT_GT(above_one, 100) << "the test is meant to include noisy values above 1";
  EXPECT_NEAR(s.mean, k, 3.0 * s.deviation / std::sqrt(200.0));
  EXPECT_NEAR(s.deviation / predicted, 1.0, 0.2);
}

// A curve that stops short of 0.8 never reaches it in the data (NaN) though the fit extrapolates;
// a flat M = 0 pins k at 0 (no mixing seen); mixed from the first sample pins it at +inf.
TEST(MixingRate, NeverMixingAndDegenerateData) {
  std::vector<double> times, slow, flat, mixed;
  for (int i = 0; i <= 20; ++i) {
    times.push_back(0.1 * i);
    slow.push_back(1.0 - std::exp(-0.4 * times.back()));  // M(2 s) = 0.55
    flat.push_back(0.0);
    mixed.push_back(i == 0 ? 0.0 : 1.0);
  }
  const MixingRate slow_fit = fit_mixing_rate(times, slow);
  EXPECT_TRUE(slow_fit.valid);
  EXPECT_NEAR(slow_fit.rate, 0.4, 1e-10);
  EXPECT_TRUE(std::isnan(slow_fit.time_to_08_data));
  EXPECT_GT(slow_fit.time_to_08_fit, times.back());

  const MixingRate flat_fit = fit_mixing_rate(times, flat);
  EXPECT_FALSE(flat_fit.valid);
  EXPECT_EQ(flat_fit.rate, 0.0);
  EXPECT_TRUE(std::isinf(flat_fit.time_to_08_fit));
  EXPECT_TRUE(std::isnan(flat_fit.time_to_08_data));

  const MixingRate mixed_fit = fit_mixing_rate(times, mixed);
  EXPECT_FALSE(mixed_fit.valid);
  EXPECT_TRUE(std::isinf(mixed_fit.rate));
  EXPECT_NEAR(mixed_fit.time_to_08_data, 0.08, 1e-12);

  const MixingRate short_fit = fit_mixing_rate({0.0, 1.0}, {0.0, 0.5});
  EXPECT_FALSE(short_fit.valid);
  EXPECT_TRUE(std::isnan(short_fit.rate));
  EXPECT_THROW(fit_mixing_rate({0.0}, {}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Segregation indices, against hand-computed values (exact up to round-off).

TEST(Segregation, HeightIndexByHand) {
  // Species 0 at heights 1 and 3 (mean 2), species 1 at 0.5 and 1.5 (mean 1), species 2 ignored.
  const std::vector<Vec3> positions = {
      {0, 0, 1.0}, {0, 0, 3.0}, {0, 0, 0.5}, {0, 0, 1.5}, {0, 0, 9.0}};
  const std::vector<std::uint32_t> species = {0, 0, 1, 1, 2};
  EXPECT_NEAR(segregation_index(positions, species, 0, 1, 0.0), 2.0 * (2.0 - 1.0) / 3.0, 1e-15);
  EXPECT_NEAR(segregation_index(positions, species, 0, 1, 0.5), 2.0 * (1.5 - 0.5) / 2.0, 1e-15);
  EXPECT_NEAR(segregation_index(positions, species, 1, 0, 0.0), -2.0 / 3.0, 1e-15);
  EXPECT_TRUE(std::isnan(segregation_index(positions, species, 0, 7, 0.0)));
  EXPECT_THROW(segregation_index(positions, species, 0, 1, 0.0, 3), std::invalid_argument);
}

TEST(Segregation, RoweNienowIndexByHand) {
  // Jetsam (0): r^3 = 1, two below and one above z = 1. Flotsam (1): r^3 = 2, one below, two
  // above. x_mean = 3/9, x_upper = 1/5, M_RN = 0.6.
  const double r1 = 1.0, r2 = std::cbrt(2.0);
  const std::vector<Vec3> positions = {{0, 0, 0.5}, {0, 0, 0.2}, {0, 0, 1.5},
                                       {0, 0, 0.7}, {0, 0, 1.2}, {0, 0, 1.9}};
  const std::vector<std::uint32_t> species = {0, 0, 0, 1, 1, 1};
  const std::vector<double> radii = {r1, r1, r1, r2, r2, r2};
  EXPECT_NEAR(rowe_nienow_index(positions, species, radii, 0, 1, 1.0), 0.6, 1e-14);
  EXPECT_TRUE(std::isnan(rowe_nienow_index(positions, species, radii, 0, 1, 5.0)));
}

}  // namespace
}  // namespace carom
