#include "scenarios/analysis/spectrum.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>

#include "core/nan.hpp"

namespace carom {

namespace {

/// The mean, the de-meaned series and its standard deviation into `s`; false when too short.
bool spectrum_setup(const std::vector<double>& values, double interval, Spectrum& s,
                    std::vector<double>& fluctuation) {
  s.interval = interval;
  s.samples = values.size();
  s.mean = s.standard_deviation = s.dominant_frequency = s.dominant_amplitude = kNaN;
  if (values.size() < 2) return false;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(values.size());
  double square = 0.0;
  fluctuation.resize(values.size());
  for (std::size_t n = 0; n < values.size(); ++n) {
    fluctuation[n] = values[n] - s.mean;
    square += fluctuation[n] * fluctuation[n];
  }
  s.standard_deviation = std::sqrt(square / static_cast<double>(values.size()));
  return true;
}

/// Amplitudes from the transform's coefficients X_1 .. X_{N/2}, and the dominant peak.
void spectrum_from_coefficients(const std::vector<std::complex<double>>& coefficient, Spectrum& s) {
  const std::size_t N = s.samples, half = N / 2;
  const double T = static_cast<double>(N) * s.interval;
  s.frequency.resize(half);
  s.amplitude.resize(half);
  for (std::size_t k = 1; k <= half; ++k) {
    const double scale = (2 * k == N ? 1.0 : 2.0) / static_cast<double>(N);
    s.frequency[k - 1] = static_cast<double>(k) / T;
    s.amplitude[k - 1] = scale * std::abs(coefficient[k]);
  }
  std::size_t peak = 0;
  for (std::size_t k = 1; k < half; ++k)
    if (s.amplitude[k] > s.amplitude[peak]) peak = k;
  if (half > 0) {
    s.dominant_frequency = s.frequency[peak];
    s.dominant_amplitude = s.amplitude[peak];
  }
}

}  // namespace

Spectrum amplitude_spectrum(const std::vector<double>& values, double interval) {
  Spectrum s;
  std::vector<double> fluctuation;
  if (!spectrum_setup(values, interval, s, fluctuation)) return s;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> coefficient;
  fft.fwd(coefficient, fluctuation);
  spectrum_from_coefficients(coefficient, s);
  return s;
}

Spectrum amplitude_spectrum_by_sum(const std::vector<double>& values, double interval) {
  Spectrum s;
  std::vector<double> fluctuation;
  if (!spectrum_setup(values, interval, s, fluctuation)) return s;
  const std::size_t N = values.size();
  std::vector<std::complex<double>> coefficient(N / 2 + 1);
  for (std::size_t k = 1; k <= N / 2; ++k)
    for (std::size_t n = 0; n < N; ++n) {
      // k n mod N keeps the angle small, so the sum is as exact as the terms.
      const double angle = -2.0 * std::numbers::pi * static_cast<double>((k * n) % N) /
                           static_cast<double>(N);
      coefficient[k] += fluctuation[n] * std::complex<double>(std::cos(angle), std::sin(angle));
    }
  spectrum_from_coefficients(coefficient, s);
  return s;
}

}  // namespace carom
