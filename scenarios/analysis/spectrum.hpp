#pragma once
/// The amplitude spectrum of an evenly sampled series (a gas pressure at a probe, a bed height):
/// the periodogram of the de-meaned series by a discrete Fourier transform.
///
/// With N samples x_n at the interval dt (T = N dt), the mean removed,
///   X_k = sum_n x_n exp(-2 pi i k n / N),   f_k = k / T,   k = 1 .. floor(N/2),
///   A_k = 2 |X_k| / N  (k < N/2),   A_{N/2} = |X_{N/2}| / N  (N even),
/// so a sine a sin(2 pi f t + phase) with f on a frequency of the grid (f = k/T) gives A_k = a
/// exactly and nothing elsewhere; off the grid its peak lies within half a bin (1/(2T)) of f and
/// is lower (leakage). The resolution is 1/T, the highest frequency the Nyquist limit 1/(2 dt).
/// Parseval: sum_k A_k^2 / 2 (the Nyquist term A^2 in full) is the variance of the series.
#include <cmath>
#include <cstddef>
#include <vector>

namespace carom {

/// A series' spectrum and the numbers a researcher reads from it.
struct Spectrum {
  double interval = 0;             ///< dt, s.
  std::size_t samples = 0;         ///< N.
  double mean = 0;                 ///< Mean of the series (its unit).
  double standard_deviation = 0;   ///< Of the fluctuations about the mean (population: over N).
  std::vector<double> frequency;   ///< f_k, k = 1 .. floor(N/2), Hz.
  std::vector<double> amplitude;   ///< A_k (the series' unit).
  double dominant_frequency = 0;   ///< f_k of the largest A_k (the lowest such k), Hz.
  double dominant_amplitude = 0;   ///< That A_k.
  /// 1/T, Hz; NaN without a spectrum.
  double resolution() const {
    return samples > 1 && interval > 0 ? 1.0 / (static_cast<double>(samples) * interval) : NAN;
  }
  /// 1/(2 dt), Hz; NaN without a spectrum.
  double nyquist() const { return samples > 1 && interval > 0 ? 0.5 / interval : NAN; }
};

/// The spectrum of `values` sampled every `interval` s (at least 2 samples, else NaN numbers and
/// empty arrays). By a fast Fourier transform (Eigen's FFT module).
Spectrum amplitude_spectrum(const std::vector<double>& values, double interval);

/// The same by the plain O(N^2) sum: the oracle the tests hold the fast path to.
Spectrum amplitude_spectrum_by_sum(const std::vector<double>& values, double interval);

}  // namespace carom
