#pragma once
/// The deceleration of a body by a drag force quadratic in its speed, F = m k V^2: then
/// 1/V(t) = 1/V0 + k t, a straight line in t. Fitted by ordinary least squares with both the
/// intercept and the slope free (the fitted intercept against the known 1/V0 shows whether the
/// law holds from the start).
#include <cstddef>
#include <vector>

namespace carom {

/// The straight line 1/V = intercept + k t through the samples, with standard errors.
struct InverseSpeedFit {
  double k = 0;                ///< Slope, 1/m (F = m k V^2).
  double k_error = 0;          ///< Its standard error (OLS, residual variance / (n - 2)), 1/m.
  double intercept = 0;        ///< 1/V at t = 0, s/m.
  double intercept_error = 0;  ///< Its standard error, s/m.
  std::size_t points = 0;      ///< Samples used (those with V > 0).
  bool valid = false;          ///< At least three samples with V > 0 at two or more times.
};

/// Fits 1/V = intercept + k t to the samples (t_i, V_i) whose speed V_i is positive and finite.
InverseSpeedFit fit_inverse_speed(const std::vector<double>& times,
                                  const std::vector<double>& speeds);

}  // namespace carom
