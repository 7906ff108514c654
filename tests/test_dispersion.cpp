// Dispersion estimators on constructed data: the mean squared displacement, the early-window
// fit (fit_dispersion) and the confined fit (fit_confined_dispersion), on exact random walks
// between reflecting ends and on the exact curve. Every random input comes from a seeded
// carom::Rng.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "analysis_support.hpp"
#include "core/rng.hpp"
#include "scenarios/analysis/dispersion.hpp"

namespace carom {
namespace {

using test::Spread;
using test::spread_of;

// ---------------------------------------------------------------------------------------------
// Mean squared displacement and the early-window fit (fit_dispersion)

TEST(Dispersion, MeanSquaredDisplacementByHand) {
  const std::vector<Vec3> start = {{0, 0, 1}, {0, 0, 2}};
  const std::vector<Vec3> now = {{5, 0, 2}, {0, 9, -1}};
  EXPECT_NEAR(mean_squared_displacement(now, start, 2), (1.0 + 9.0) / 2.0, 1e-15);
  EXPECT_NEAR(mean_squared_displacement(now, start, 0), 25.0 / 2.0, 1e-15);
  EXPECT_TRUE(std::isnan(mean_squared_displacement({}, {}, 2)));
  EXPECT_THROW(mean_squared_displacement(now, {}, 2), std::invalid_argument);
}

/// MSD record of 1-D walkers with Gaussian steps of variance 2 D dt between reflecting walls at
/// 0 and H. Folding the free step back into [0, H] gives exactly the transition density of
/// reflected Brownian motion (method of images), so the samples are those of the continuum process.
struct WalkRecord {
  std::vector<double> time, msd;
};
WalkRecord random_walk(std::size_t walkers, double D, double dt, int steps, int stride, double H,
                       bool uniform_start, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> start(walkers), x(walkers);
  for (std::size_t w = 0; w < walkers; ++w)
    start[w] = x[w] = uniform_start ? H * rng.uniform() : 0.5 * H;
  const double step = std::sqrt(2.0 * D * dt);
  WalkRecord record{{0.0}, {0.0}};
  for (int n = 1; n <= steps; ++n) {
    for (double& position : x) {
      double folded = std::fmod(position + step * rng.normal(), 2.0 * H);
      if (folded < 0.0) folded += 2.0 * H;
      position = folded > H ? 2.0 * H - folded : folded;
    }
    if (n % stride != 0) continue;
    double sum = 0.0;
    for (std::size_t w = 0; w < walkers; ++w) sum += (x[w] - start[w]) * (x[w] - start[w]);
    record.time.push_back(n * dt);
    record.msd.push_back(sum / double(walkers));
  }
  return record;
}

/// Least-squares weights c_i of the slope over the samples of `record` in [start, end]; the
/// fitted D is sum_i c_i msd_i / 2.
std::vector<double> slope_weights(const WalkRecord& record, double start, double end,
                                  std::vector<double>& window_times) {
  window_times.clear();
  for (double t : record.time)
    if (t >= start && t <= end) window_times.push_back(t);
  double mean = 0.0, s_tt = 0.0;
  for (double t : window_times) mean += t;
  mean /= double(window_times.size());
  for (double t : window_times) s_tt += (t - mean) * (t - mean);
  std::vector<double> weights;
  for (double t : window_times) weights.push_back((t - mean) / s_tt);
  return weights;
}

/// Standard error of the fitted D for N free walkers: each walker's squared displacements have
/// Cov(X_i^2, X_j^2) = 2 (2 D min(t_i, t_j))^2 (Gaussian), so Var(slope) = (2/N) c^T C c exactly.
/// It is roughly D sqrt(2/N) x O(1) (the MSD's own relative spread is sqrt(2/N) at every t).
/// Reflecting walls only reduce the fluctuations, so it bounds the walled cases too.
double free_walk_standard_error(const std::vector<double>& weights, const std::vector<double>& t,
                                double D, std::size_t walkers) {
  double variance = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = 0; j < t.size(); ++j)
      variance += weights[i] * weights[j] * 2.0 * std::pow(2.0 * D * std::min(t[i], t[j]), 2);
  return 0.5 * std::sqrt(variance / double(walkers));
}

// Walls 1000 diffusion lengths away: the window is the whole record and D comes back within
// 3 exact standard errors (4000 walkers: about 2 %).
TEST(Dispersion, FreeRandomWalkRecoversCoefficient) {
  const double D = 1.0, H = 1000.0;
  const WalkRecord record = random_walk(4000, D, 5e-5, 2000, 5, H, false, 31);
  const Dispersion fit = fit_dispersion(record.time, record.msd, H * H / 6.0);
  ASSERT_TRUE(fit.valid);
  EXPECT_EQ(fit.points, record.time.size() - 1);
  std::vector<double> t;
  const std::vector<double> weights = slope_weights(record, fit.fit_start, fit.fit_end, t);
  const double error = free_walk_standard_error(weights, t, D, 4000);
  std::printf("free walk: D = %.4f +- %.4f (sqrt(2/N) = %.4f)\n", fit.coefficient, error,
              std::sqrt(2.0 / 4000.0));
  EXPECT_NEAR(fit.coefficient, D, 3.0 * error);
}

// Walls at 0 and H = 1 with walkers released at mid-height (a tagged layer): by the end the MSD
// has saturated (at H^2/12). The window stops at 5 % of H^2/6, when the walkers' rms excursion
// is 0.09 H and the walls 5.5 of those away, so D is unbiased: within 3 standard errors. Fitting
// the whole record instead (window_fraction 1) must be far off, which is why the window exists.
TEST(Dispersion, WindowStopsBeforeCloseWallsSaturate) {
  const double D = 1.0, H = 1.0;
  const WalkRecord record = random_walk(4000, D, 5e-5, 2000, 5, H, false, 32);
  ASSERT_GT(record.msd.back(), 0.4 * H * H / 6.0) << "the record must reach saturation";
  const Dispersion fit = fit_dispersion(record.time, record.msd, H * H / 6.0);
  ASSERT_TRUE(fit.valid);
  EXPECT_LT(fit.fit_end, 0.1 * record.time.back());
  std::vector<double> t;
  const std::vector<double> weights = slope_weights(record, fit.fit_start, fit.fit_end, t);
  const double error = free_walk_standard_error(weights, t, D, 4000);
  std::printf("close walls, mid start: D = %.4f +- %.4f over %zu samples\n", fit.coefficient, error,
              fit.points);
  EXPECT_NEAR(fit.coefficient, D, 3.0 * error);
  EXPECT_LT(fit_dispersion(record.time, record.msd, H * H / 6.0, 1.0).coefficient, 0.7 * D);
}

// Walkers filling the bed uniformly: the ends bias the fit low, as dispersion.hpp documents.
// The exact mean MSD of reflected Brownian motion from a uniform start is
//   H^2/6 - (16 H^2/pi^4) sum_{m odd} m^-4 exp(-m^2 pi^2 D t/H^2),
// and the fitted D is linear in the samples, so its expectation is the fit applied to that
// curve: the measured D must match it within 3 standard errors, and the bias must be the
// documented -0.45 sqrt(window_fraction) within 20 % (the formula is the continuum-window limit).
TEST(Dispersion, UniformTracersFollowDocumentedWallBias) {
  const double D = 1.0, H = 1.0, window = 0.05;
  const WalkRecord record = random_walk(4000, D, 5e-5, 2000, 5, H, true, 33);
  const Dispersion fit = fit_dispersion(record.time, record.msd, H * H / 6.0, window);
  ASSERT_TRUE(fit.valid);
  std::vector<double> t;
  const std::vector<double> weights = slope_weights(record, fit.fit_start, fit.fit_end, t);
  double expected = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    double series = 0.0;
    for (int m = 1; m < 400; m += 2)
      series += std::pow(m, -4.0) *
                std::exp(-m * m * std::numbers::pi * std::numbers::pi * D * t[i] / (H * H));
    const double mean_msd = H * H / 6.0 - 16.0 * H * H / std::pow(std::numbers::pi, 4) * series;
    expected += 0.5 * weights[i] * mean_msd;
  }
  const double error = free_walk_standard_error(weights, t, D, 4000);
  std::printf("close walls, uniform start: D = %.4f, expected %.4f +- %.4f (bias %.3f)\n",
              fit.coefficient, expected, error, expected / D - 1.0);
  EXPECT_NEAR(fit.coefficient, expected, 3.0 * error);
  EXPECT_NEAR((expected / D - 1.0) / (-0.45 * std::sqrt(window)), 1.0, 0.2);
}

TEST(Dispersion, TooFewPointsIsInvalid) {
  const Dispersion fit = fit_dispersion({0.0, 1.0, 2.0, 3.0}, {0.0, 0.1, 0.2, 5.0}, 1.0, 0.5);
  EXPECT_EQ(fit.points, 2u);
  EXPECT_FALSE(fit.valid);
  EXPECT_NEAR(fit.coefficient, 0.05, 1e-15);
  EXPECT_FALSE(fit_dispersion({}, {}, 1.0).valid);
  EXPECT_THROW(fit_dispersion({1.0}, {1.0}, 1.0, 0.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// The confined fit (fit_confined_dispersion): the exact MSD of tracers filling a bed between
// reflecting ends, fitted over the whole record.

/// The exact curve, evaluated independently of dispersion.cpp: the series written as
/// S (96/pi^4) sum_{m odd} m^-4 (1 - exp(-m^2 pi^2 tau)) (no cancellation at small tau), summed
/// up to m = 20001 and the rest of sum m^-4 added as 1/(6 (M + 1)^3) (exact to O(M^-5); the
/// exponentials are below e^-3900 there for tau >= 1e-6). Accurate to about 1e-15 relative.
double brute_force_confined_msd(double time, double D, double saturation) {
  const double pi = std::numbers::pi, tau = D * time / (6.0 * saturation);
  const int last = 20001;
  double sum = 1.0 / (6.0 * std::pow(last + 1.0, 3));
  for (int m = last; m >= 1; m -= 2) {  // smallest terms first
    const double mm = double(m) * m;
    sum += -std::expm1(-mm * pi * pi * tau) / (mm * mm);
  }
  return saturation * 96.0 / std::pow(pi, 4) * sum;
}

// The model against its brute-force twin from tau = D t/H^2 = 1e-6 to 3, both sides of the
// switch between the short-time form and the series at tau = 0.01 included: 1e-12 relative (the
// model's own error is below 1e-14 there, the twin's about 1e-15; the margin is for round-off
// in 1e4-term sums). In SI units of a real bed: H = 8 cm, D = 3e-4 m^2/s.
TEST(ConfinedDispersion, CurveAgreesWithBruteForceSeries) {
  const double H = 0.08, D = 3e-4, S = H * H / 6.0;
  double worst = 0.0;
  for (double tau : {1e-6, 1e-4, 1e-3, 0.005, 0.0099, 0.01, 0.0101, 0.02, 0.05, 0.2, 1.0, 3.0}) {
    const double t = tau * H * H / D;
    const double model = confined_mean_squared_displacement(t, D, S);
    const double brute = brute_force_confined_msd(t, D, S);
    worst = std::max(worst, std::abs(model / brute - 1.0));
    EXPECT_NEAR(model / brute, 1.0, 1e-12) << "tau = " << tau;
  }
  std::printf("confined MSD against the brute-force series: worst relative error %.2e\n", worst);
  // The short-time form that fit_dispersion's documented wall bias comes from:
  // 2 D t [1 - (8/(3 sqrt(2 pi))) sqrt(2 D t)/H], exact up to O(exp(-H^2/(4 D t))).
  const double early = 1e-4 * H * H / D;
  const double wall_correction =
      8.0 / (3.0 * std::sqrt(2.0 * std::numbers::pi)) * std::sqrt(2.0 * D * early) / H;
  EXPECT_NEAR(
      confined_mean_squared_displacement(early, D, S) / (2.0 * D * early * (1.0 - wall_correction)),
      1.0, 1e-12);
  EXPECT_NEAR(confined_mean_squared_displacement(10.0 * H * H / D, D, S), S, 1e-15 * S);
  EXPECT_EQ(confined_mean_squared_displacement(0.0, D, S), 0.0);
  EXPECT_TRUE(std::isnan(confined_mean_squared_displacement(-1.0, D, S)));
}

// The exact curve (the brute-force twin), sampled densely from t = 0 to 2 H^2/D (given out of
// order, with a NaN sample and a negative time that must be skipped) and sparsely (5 samples):
// the bisection solves the normal equation to round-off and the model is exact to 1e-14, so D
// comes back to 1e-10 (measured: about 1e-14).
TEST(ConfinedDispersion, ExactCurveRecoversCoefficient) {
  const double H = 0.08, D = 3e-4, S = H * H / 6.0, saturation_time = H * H / D;
  std::vector<double> times, msd;
  for (int i = 200; i >= 0; --i) {
    times.push_back(0.01 * i * saturation_time);
    msd.push_back(brute_force_confined_msd(times.back(), D, S));
  }
  msd[17] = std::numeric_limits<double>::quiet_NaN();
  times.push_back(-1.0), msd.push_back(0.0);
  const Dispersion dense = fit_confined_dispersion(times, msd, S);
  ASSERT_TRUE(dense.valid);
  EXPECT_EQ(dense.points, 200u);
  EXPECT_EQ(dense.fit_start, 0.0);
  EXPECT_NEAR(dense.fit_end, 2.0 * saturation_time, 1e-12 * saturation_time);
  EXPECT_NEAR(dense.coefficient / D, 1.0, 1e-10);

  std::vector<double> sparse_times, sparse_msd;
  for (int i = 1; i <= 5; ++i) {
    sparse_times.push_back(0.05 * i * saturation_time);
    sparse_msd.push_back(brute_force_confined_msd(sparse_times.back(), D, S));
  }
  const Dispersion sparse = fit_confined_dispersion(sparse_times, sparse_msd, S);
  ASSERT_TRUE(sparse.valid);
  EXPECT_NEAR(sparse.coefficient / D, 1.0, 1e-10);
  std::printf("exact curve: D relative error %.1e (201 samples), %.1e (5 samples)\n",
              dense.coefficient / D - 1.0, sparse.coefficient / D - 1.0);
}

// Uniform tracers between reflecting ends, sampled as in UniformTracersFollowDocumentedWallBias
// (every 2.5e-4 H^2/D up to 0.1 H^2/D, 4000 walkers). The fit's standard error is estimated from
// 25 records of 1000 walkers with other seeds and scaled by sqrt(1000/4000): the MSD is a mean
// over independent walkers, so its covariance goes as 1/N, and the fit is linear in it up to
// O(SE^2/D) (least squares: unbiased to that order too). (The walk is exact at any step, so these
// records take one step per sample.) The record of that test (seed 33) must give D within 3 SE,
// and the mean of the 25 within 3 of its standard errors (a 0.3 % chance each to fail by bad
// luck, fixed by the seeds). The early-window fit on the same records is printed for
// comparison: about 10 % low, with a similar spread.
TEST(ConfinedDispersion, UniformTracersRecoverCoefficient) {
  const double D = 1.0, H = 1.0, S = H * H / 6.0;
  const std::size_t walkers = 4000, repetition_walkers = 1000, repetitions = 25;
  std::vector<double> confined, windowed;
  for (std::size_t r = 0; r < repetitions; ++r) {
    const WalkRecord record = random_walk(repetition_walkers, D, 2.5e-4, 400, 1, H, true, 3300 + r);
    const Dispersion fit = fit_confined_dispersion(record.time, record.msd, S);
    ASSERT_TRUE(fit.valid);
    confined.push_back(fit.coefficient);
    windowed.push_back(fit_dispersion(record.time, record.msd, S).coefficient);
  }
  const Spread c = spread_of(confined), w = spread_of(windowed);
  const double mean_error = c.deviation / std::sqrt(double(repetitions));
  const double error = c.deviation * std::sqrt(double(repetition_walkers) / double(walkers));
  std::printf(
      "uniform tracers, 25 records of 1000: confined D = %.4f +- %.4f (sd %.4f), early "
      "window D = %.4f (sd %.4f)\n",
      c.mean, mean_error, c.deviation, w.mean, w.deviation);
  EXPECT_NEAR(c.mean, D, 3.0 * mean_error);

  const WalkRecord record = random_walk(walkers, D, 5e-5, 2000, 5, H, true, 33);
  const Dispersion fit = fit_confined_dispersion(record.time, record.msd, S);
  ASSERT_TRUE(fit.valid);
  EXPECT_EQ(fit.points, record.time.size());
  std::printf("uniform tracers, seed 33 (4000): confined D = %.4f +- %.4f\n", fit.coefficient,
              error);
  EXPECT_NEAR(fit.coefficient, D, 3.0 * error);
}

// Five samples over the saturation time (t = 0.05 ... 0.25 H^2/D, the first already at 40 % of
// the plateau): the early window holds no sample, so fit_dispersion is invalid on every record,
// while the confined fit recovers D. 200 records of 4000 walkers: the mean within 3 standard
// errors of the mean (sd/sqrt(200)), every record within 5 sd (a 1e-4 chance over 200 for
// Gaussian errors).
TEST(ConfinedDispersion, SparseSamplingStillRecoversCoefficient) {
  const double D = 1.0, H = 1.0, S = H * H / 6.0;
  const std::size_t repetitions = 200;
  std::vector<double> confined;
  for (std::size_t r = 0; r < repetitions; ++r) {
    const WalkRecord record = random_walk(4000, D, 0.05, 5, 1, H, true, 5100 + r);
    ASSERT_EQ(record.time.size(), 6u);  // t = 0 and five samples
    const Dispersion windowed = fit_dispersion(record.time, record.msd, S);
    EXPECT_FALSE(windowed.valid);
    EXPECT_EQ(windowed.points, 0u);
    const Dispersion fit = fit_confined_dispersion(record.time, record.msd, S);
    ASSERT_TRUE(fit.valid);
    EXPECT_EQ(fit.points, 6u);
    confined.push_back(fit.coefficient);
  }
  const Spread c = spread_of(confined);
  const double mean_error = c.deviation / std::sqrt(double(repetitions));
  std::printf("sparse sampling, 200 records: confined D = %.4f +- %.4f (sd %.4f)\n", c.mean,
              mean_error, c.deviation);
  EXPECT_NEAR(c.mean, D, 3.0 * mean_error);
  for (double coefficient : confined) EXPECT_NEAR(coefficient, D, 5.0 * c.deviation);
}

// No motion pins D at 0, saturation from the first sample at +inf (both invalid); fewer than two
// positive times give NaN; user errors throw.
TEST(ConfinedDispersion, DegenerateData) {
  const double S = 1.0 / 6.0;
  const std::vector<double> times = {0.0, 0.5, 1.0, 1.5};
  const Dispersion still = fit_confined_dispersion(times, {0.0, 0.0, 0.0, 0.0}, S);
  EXPECT_FALSE(still.valid);
  EXPECT_EQ(still.coefficient, 0.0);
  const Dispersion saturated = fit_confined_dispersion(times, {0.0, S, S, S}, S);
  EXPECT_FALSE(saturated.valid);
  EXPECT_TRUE(std::isinf(saturated.coefficient));
  const Dispersion one = fit_confined_dispersion({0.0, 1.0}, {0.0, 0.01}, S);
  EXPECT_FALSE(one.valid);
  EXPECT_TRUE(std::isnan(one.coefficient));
  EXPECT_EQ(one.points, 2u);
  EXPECT_FALSE(fit_confined_dispersion({}, {}, S).valid);
  EXPECT_THROW(fit_confined_dispersion({1.0}, {}, S), std::invalid_argument);
  EXPECT_THROW(fit_confined_dispersion({1.0}, {0.1}, 0.0), std::invalid_argument);
  EXPECT_THROW(fit_confined_dispersion({1.0}, {0.1}, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace carom
