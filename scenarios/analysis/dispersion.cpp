#include "scenarios/analysis/dispersion.hpp"

#include "core/nan.hpp"
#include "scenarios/analysis/log_least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace carom {

namespace {
}  // namespace

double mean_squared_displacement(const std::vector<Vec3>& now, const std::vector<Vec3>& start,
                                 int axis) {
  if (now.size() != start.size())
    throw std::invalid_argument("mean_squared_displacement: " + std::to_string(now.size()) +
                                " positions now but " + std::to_string(start.size()) +
                                " at the start");
  if (axis < 0 || axis > 2)
    throw std::invalid_argument("mean_squared_displacement: the axis must be 0, 1 or 2, not " +
                                std::to_string(axis));
  if (now.empty()) return kNaN;
  double sum = 0.0;
  for (std::size_t i = 0; i < now.size(); ++i) {
    const double displacement = now[i][axis] - start[i][axis];
    sum += displacement * displacement;
  }
  return sum / double(now.size());
}

Dispersion fit_dispersion(const std::vector<double>& times, const std::vector<double>& msd,
                          double saturation_msd, double window_fraction) {
  if (times.size() != msd.size())
    throw std::invalid_argument("fit_dispersion: " + std::to_string(times.size()) + " times but " +
                                std::to_string(msd.size()) + " MSD values");
  if (!(window_fraction > 0.0 && window_fraction <= 1.0))
    throw std::invalid_argument("fit_dispersion: window_fraction must lie in (0, 1]");

  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < times.size(); ++i)
    if (std::isfinite(times[i]) && times[i] > 0.0 && std::isfinite(msd[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return times[i] < times[j]; });

  const bool bounded = std::isfinite(saturation_msd) && saturation_msd > 0.0;
  const double window_msd =
      bounded ? window_fraction * saturation_msd : std::numeric_limits<double>::infinity();
  std::vector<double> t, y;
  for (std::size_t i : order) {
    if (msd[i] > window_msd) break;
    t.push_back(times[i]);
    y.push_back(msd[i]);
  }

  Dispersion result{kNaN, kNaN, kNaN, t.size(), false};
  if (t.empty()) return result;
  result.fit_start = t.front();
  result.fit_end = t.back();
  if (t.size() < 2) return result;

  // Least-squares line y = a + b t, in deviations from the means (well conditioned).
  double mean_t = 0.0, mean_y = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) mean_t += t[i], mean_y += y[i];
  mean_t /= double(t.size());
  mean_y /= double(t.size());
  double s_tt = 0.0, s_ty = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    s_tt += (t[i] - mean_t) * (t[i] - mean_t);
    s_ty += (t[i] - mean_t) * (y[i] - mean_y);
  }
  if (s_tt <= 0.0) return result;  // every sample at the same time
  result.coefficient = 0.5 * s_ty / s_tt;
  result.valid = t.size() >= 3 && result.coefficient > 0.0;
  return result;
}

// ---------------------------------------------------------------------------------------------
// Tracers filling a bed between reflecting ends

namespace {

/// Below this tau = D t/H^2 the short-time form replaces the series. Its neglected image terms
/// are below 1e-14 relative there, and the series needs about 10 terms to reach 1e-18.
constexpr double kShortTime = 0.01;

/// The saturating shape f(tau) = MSD/S of confined_mean_squared_displacement, tau = D t/H^2.
double confined_shape(double tau) {
  constexpr double pi = std::numbers::pi;
  if (tau < kShortTime) {
    // The theta-function (image) form of the series: f'' = -(24/sqrt(pi tau)) (1 + 2 sum_k>=1
    // (-1)^k exp(-k^2/(4 tau))) with f(0) = 0, f'(0) = 12; the image terms are dropped.
    return 12.0 * tau - 32.0 / std::sqrt(pi) * tau * std::sqrt(tau);
  }
  double sum = 0.0;  // sum_{m odd} m^-4 exp(-m^2 pi^2 tau), terms falling faster than geometric
  for (int m = 1; m < 1000; m += 2) {
    const double term = std::exp(-double(m) * m * pi * pi * tau) / (double(m) * m * m * m);
    sum += term;
    if (term <= 1e-18 * sum) break;  // also when exp underflows
  }
  return 1.0 - 96.0 / (pi * pi * pi * pi) * sum;
}

/// df/dtau of confined_shape.
double confined_shape_slope(double tau) {
  constexpr double pi = std::numbers::pi;
  if (tau < kShortTime) return 12.0 - 48.0 * std::sqrt(tau / pi);
  double sum = 0.0;  // sum_{m odd} m^-2 exp(-m^2 pi^2 tau)
  for (int m = 1; m < 1000; m += 2) {
    const double term = std::exp(-double(m) * m * pi * pi * tau) / (double(m) * m);
    sum += term;
    if (term <= 1e-18 * sum) break;  // also when exp underflows
  }
  return 96.0 / (pi * pi) * sum;
}

/// The samples a confined fit uses, in time order, and the plateau S = H^2/6 they tend to.
struct ConfinedRecord {
  std::vector<double> time, msd;
  double saturation;

  double tau(double coefficient, double t) const { return coefficient * t / (6.0 * saturation); }
  /// Sum of squared residuals of S f(D t/H^2).
  double squared_residuals(double coefficient) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      const double residual = msd[i] - saturation * confined_shape(tau(coefficient, time[i]));
      sum += residual * residual;
    }
    return sum;
  }
  /// sum_i r_i t_i f'(tau_i), proportional to -dF/dD: positive where F falls with D.
  double normal_equation(double coefficient) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      const double t = tau(coefficient, time[i]);
      const double residual = msd[i] - saturation * confined_shape(t);
      sum += residual * time[i] * confined_shape_slope(t);
    }
    return sum;
  }
};

}  // namespace

double confined_mean_squared_displacement(double time, double coefficient, double saturation_msd) {
  if (!(std::isfinite(time) && time >= 0.0)) return kNaN;
  return saturation_msd * confined_shape(coefficient * time / (6.0 * saturation_msd));
}

Dispersion fit_confined_dispersion(const std::vector<double>& times, const std::vector<double>& msd,
                                   double saturation_msd) {
  if (times.size() != msd.size())
    throw std::invalid_argument("fit_confined_dispersion: " + std::to_string(times.size()) +
                                " times but " + std::to_string(msd.size()) + " MSD values");
  if (!(std::isfinite(saturation_msd) && saturation_msd > 0.0))
    throw std::invalid_argument(
        "fit_confined_dispersion: saturation_msd must be finite and positive (H^2/6 of the bed "
        "the tracers fill); for an unbounded direction use fit_dispersion");

  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < times.size(); ++i)
    if (std::isfinite(times[i]) && times[i] >= 0.0 && std::isfinite(msd[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return times[i] < times[j]; });
  ConfinedRecord record{{}, {}, saturation_msd};
  for (std::size_t i : order) {
    record.time.push_back(times[i]);
    record.msd.push_back(msd[i]);
  }

  Dispersion result{kNaN, kNaN, kNaN, record.time.size(), false};
  if (record.time.empty()) return result;
  result.fit_start = record.time.front();
  result.fit_end = record.time.back();
  const auto first_positive =
      std::find_if(record.time.begin(), record.time.end(), [](double t) { return t > 0.0; });
  if (record.time.end() - first_positive < 2) return result;

  // D over the range the data can resolve (H^2 = 6 S).
  const double height_squared = 6.0 * saturation_msd;
  const LogFit fit = minimize_on_log_range(record, std::log(1e-8 * height_squared / record.time.back()),
                                           std::log(1e2 * height_squared / *first_positive));
  result.coefficient = fit.value;
  result.valid = fit.valid;
  return result;
}

}  // namespace carom
