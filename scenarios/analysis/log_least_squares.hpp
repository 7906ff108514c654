#pragma once
/// One-parameter least squares over a logarithmic range, shared by the mixing-rate fit
/// (mixing.cpp) and the confined-dispersion fit (dispersion.cpp). It cannot diverge: F(p) is
/// scanned on a grid of ln p (40 points per decade), and the best grid point is refined by
/// bisection in ln p on the normal equation between its neighbours (golden-section search on F
/// where the signs do not bracket it), to round-off.
#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

/// The fitted parameter; valid is false when the best grid point is an end of the range
/// (value 0 at the lower end: nothing seen; +inf at the upper end: saturated at once).
struct LogFit {
  double value = 0.0;
  bool valid = false;
};

/// `curve` provides squared_residuals(p) (F) and normal_equation(p), positive where F falls
/// with p. The range is [exp(lo), exp(hi)], lo < hi.
template <class Curve>
LogFit minimize_on_log_range(const Curve& curve, double lo, double hi) {
  const double step = std::log(10.0) / 40.0;
  const int intervals = std::max(2, static_cast<int>(std::ceil((hi - lo) / step)));
  const auto grid_point = [&](int j) { return lo + (hi - lo) * j / intervals; };
  int best = 0;
  double best_residual = std::numeric_limits<double>::infinity();
  for (int j = 0; j <= intervals; ++j) {
    const double residual = curve.squared_residuals(std::exp(grid_point(j)));
    // The last of equal values: a plateau of F reaching the upper end (the model saturated at
    // every positive sample) means the parameter is pinned there, not at the plateau's start.
    if (residual <= best_residual) best_residual = residual, best = j;
  }
  if (best == 0) return {0.0, false};
  if (best == intervals) return {std::numeric_limits<double>::infinity(), false};

  double a = grid_point(best - 1), b = grid_point(best + 1);
  if (curve.normal_equation(std::exp(a)) > 0.0 && curve.normal_equation(std::exp(b)) < 0.0) {
    // F falls at a and rises at b: bisection on the normal equation, to round-off.
    for (int iteration = 0; iteration < 200; ++iteration) {
      const double mid = 0.5 * (a + b);
      if (mid <= a || mid >= b) break;
      (curve.normal_equation(std::exp(mid)) > 0.0 ? a : b) = mid;
    }
    return {std::exp(0.5 * (a + b)), true};
  }
  // Not bracketed by signs (flat or ragged F): golden-section search on F itself.
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
  double f1 = curve.squared_residuals(std::exp(x1)), f2 = curve.squared_residuals(std::exp(x2));
  for (int iteration = 0; iteration < 200 && b - a > 1e-15 * (1.0 + std::abs(a)); ++iteration) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - golden * (b - a);
      f1 = curve.squared_residuals(std::exp(x1));
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + golden * (b - a);
      f2 = curve.squared_residuals(std::exp(x2));
    }
  }
  return {std::exp(0.5 * (a + b)), true};
}

}  // namespace carom
