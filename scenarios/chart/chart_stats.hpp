#pragma once
/// The statistics of a chart: per variant the mean over seeds and its standard error, the
/// error against the reference with its uncertainty, the Pareto front of error against cost,
/// and the cheapest variant within a tolerance. Plain functions on numbers (tested on
/// constructed data in tests/test_chart_stats.cpp); nothing here knows about runs or files.
///
/// Conventions (CHARTS.md says them to users):
///   standard error  s = sd / sqrt(n), sd with n - 1 in the denominator; NaN when n < 2.
///   absolute error  E = m_v - m_r, uncertainty u = sqrt(s_v^2 + s_r^2) (independent seeds
///                   combined), own noise s_v.
///   relative error  E = m_v / m_r - 1, u = sqrt(s_v^2 + (m_v / m_r)^2 s_r^2) / |m_r| (first-
///                   order propagation of both), own noise s_v / |m_r|.
///   the reference   E = 0, u = its own noise (it is compared with nothing but itself).
///   within noise    |E| < u: the error is not resolved by these seeds.
#include <cstddef>
#include <optional>
#include <vector>

#include "scenarios/chart/chart_spec.hpp"

namespace carom {

/// Mean and standard error of a quantity over seeds.
struct SeedStatistics {
  std::size_t count = 0;      ///< Finite values used (NaN values are left out).
  double mean = 0;            ///< NaN when count == 0.
  double standard_error = 0;  ///< sd / sqrt(n); NaN when count < 2.
};

/// The statistics of the finite values among `values`.
SeedStatistics seed_statistics(const std::vector<double>& values);

/// A variant's error against the reference, in the observable's measure.
struct ErrorEstimate {
  double error = 0;           ///< E (signed); NaN when either mean is missing.
  double uncertainty = 0;     ///< u: one standard error of E; NaN when a standard error is.
  double noise = 0;           ///< The variant's own standard error in the same measure.
  bool within_noise = false;  ///< |E| < u.
};

/// Error of `variant` against `reference`. `is_reference`: the variant is the reference itself.
ErrorEstimate error_against_reference(const SeedStatistics& variant,
                                      const SeedStatistics& reference, ErrorMeasure measure,
                                      bool is_reference);

/// A variant as a point of the chart.
struct ChartPoint {
  double cost = 0;   ///< CPU seconds per simulated second (NaN: missing).
  double error = 0;  ///< |E| (NaN: missing).
  double noise = 0;  ///< Its own standard error in the error's measure (NaN: unknown).
};

/// Where a point stands against the others.
struct FrontMembership {
  /// No other point is at least as cheap and at least as accurate and better in one of them.
  bool on_front = false;
  /// Not on the front, but every point that dominates it is more accurate by less than the
  /// noise of the two, sqrt(noise_a^2 + noise_b^2) (strictly; an unknown noise never
  /// qualifies): these seeds cannot tell that it is off the front.
  bool dominated_within_noise = false;
};

/// The Pareto front of minimal cost and minimal error (ties: both stay on it). Points with a
/// missing cost or error take no part (neither on the front nor dominating).
std::vector<FrontMembership> pareto_front(const std::vector<ChartPoint>& points);

/// The cheapest point with error <= tolerance, other than `excluded` (the reference); equal
/// costs go to the smaller error, then the earlier point. nullopt when none qualifies.
std::optional<std::size_t> cheapest_within(const std::vector<ChartPoint>& points, double tolerance,
                                           std::size_t excluded);

}  // namespace carom
