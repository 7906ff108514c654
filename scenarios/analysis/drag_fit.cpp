#include "scenarios/analysis/drag_fit.hpp"

#include <cmath>

namespace carom {

InverseSpeedFit fit_inverse_speed(const std::vector<double>& times,
                                  const std::vector<double>& speeds) {
  InverseSpeedFit fit;
  std::vector<double> t, y;
  for (std::size_t i = 0; i < times.size() && i < speeds.size(); ++i)
    if (std::isfinite(speeds[i]) && speeds[i] > 0.0 && std::isfinite(times[i])) {
      t.push_back(times[i]);
      y.push_back(1.0 / speeds[i]);
    }
  const std::size_t n = t.size();
  fit.points = n;
  if (n < 3) return fit;
  double t_mean = 0.0, y_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) t_mean += t[i], y_mean += y[i];
  t_mean /= static_cast<double>(n);
  y_mean /= static_cast<double>(n);
  double stt = 0.0, sty = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    stt += (t[i] - t_mean) * (t[i] - t_mean);
    sty += (t[i] - t_mean) * (y[i] - y_mean);
  }
  if (!(stt > 0.0)) return fit;
  fit.k = sty / stt;
  fit.intercept = y_mean - fit.k * t_mean;
  double residuals = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - fit.intercept - fit.k * t[i];
    residuals += r * r;
  }
  const double variance = residuals / static_cast<double>(n - 2);
  fit.k_error = std::sqrt(variance / stt);
  fit.intercept_error =
      std::sqrt(variance * (1.0 / static_cast<double>(n) + t_mean * t_mean / stt));
  fit.valid = true;
  return fit;
}

}  // namespace carom
