#include "events/soft_sphere/hertz_damping.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>

namespace carom {

namespace {

/// x'' for the dimensionless damped Hertz impact (x < 0 cannot occur before the end).
double acceleration(double x, double v, double zeta) {
  const double xp = x > 0.0 ? x : 0.0;
  return -xp * std::sqrt(xp) - zeta * std::sqrt(std::sqrt(xp)) * v;
}

}  // namespace

double hertz_restitution(double beta) {
  const double zeta = std::sqrt(5.0) * beta;
  const double h = 2e-4;
  double x = 0.0, v = 1.0;
  for (int step = 0; step < 10'000'000; ++step) {
    const double k1x = v, k1v = acceleration(x, v, zeta);
    const double k2x = v + 0.5 * h * k1v, k2v = acceleration(x + 0.5 * h * k1x, k2x, zeta);
    const double k3x = v + 0.5 * h * k2v, k3v = acceleration(x + 0.5 * h * k2x, k3x, zeta);
    const double k4x = v + h * k3v, k4v = acceleration(x + h * k3x, k4x, zeta);
    const double x_next = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    const double v_next = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    if (x_next <= 0.0 && step > 0) {
      // Contact ends between the two points: cubic Hermite interpolation of x, and the
      // velocity at that instant from the Hermite derivative.
      double lo = 0.0, hi = 1.0;
      auto hermite = [&](double s) {
        const double s2 = s * s, s3 = s2 * s;
        return (2 * s3 - 3 * s2 + 1) * x + (s3 - 2 * s2 + s) * h * v + (-2 * s3 + 3 * s2) * x_next +
               (s3 - s2) * h * v_next;
      };
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (hermite(mid) > 0.0 ? lo : hi) = mid;
      }
      const double s = 0.5 * (lo + hi), s2 = s * s;
      const double slope = ((6 * s2 - 6 * s) * x + (3 * s2 - 4 * s + 1) * h * v +
                            (-6 * s2 + 6 * s) * x_next + (3 * s2 - 2 * s) * h * v_next) / h;
      return -slope;
    }
    if (v_next <= 0.0 && x_next <= 0.0) return 0.0;
    x = x_next;
    v = v_next;
    if (x <= 0.0 && v <= 0.0) return 0.0;
  }
  return 0.0;  // overdamped beyond any physical e: the sphere never comes back
}

double hertz_damping_for_restitution(double e) {
  if (!(e > 0.0 && e <= 1.0))
    throw std::invalid_argument("restitution " + std::to_string(e) + " is outside (0, 1]");
  if (e == 1.0) return 0.0;
  // A scene has few distinct restitutions, and each inversion costs ~0.1 s: remember them.
  static std::mutex guard;
  static std::map<double, double> known;
  {
    const std::lock_guard<std::mutex> lock(guard);
    const auto found = known.find(e);
    if (found != known.end()) return found->second;
  }
  double lo = 0.0, hi = 1.0;
  while (hertz_restitution(hi) > e) hi *= 2.0;  // restitution falls monotonically with beta
  while (hi - lo > 1e-10 * hi) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution(mid) > e ? lo : hi) = mid;
  }
  const double beta = 0.5 * (lo + hi);
  const std::lock_guard<std::mutex> lock(guard);
  known.emplace(e, beta);
  return beta;
}

double liggghts_damping(double e) {
  if (!(e > 0.0 && e <= 1.0))
    throw std::invalid_argument("restitution " + std::to_string(e) + " is outside (0, 1]");
  const double l = std::log(e);
  return -l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

}  // namespace carom
