#pragma once
/// The `relax` flight model: exact flight under gravity plus a linear drag frozen for one fluid
/// step (ballistic-plus-drag). See core/DESIGN.md, "Particles and flights".
#include <algorithm>
#include <cmath>

#include "vec3.hpp"

namespace carom {

/// phi1(x) = (1 - e^-x) / x, with phi1(0) = 1. Accurate for every x >= 0 (series near 0).
inline double relax_phi1(double x) {
  if (x < 1e-4) return 1.0 - x * (0.5 - x * (1.0 / 6.0 - x / 24.0));
  return -std::expm1(-x) / x;
}

/// phi2(x) = (x - 1 + e^-x) / x^2, with phi2(0) = 1/2. Accurate for every x >= 0.
inline double relax_phi2(double x) {
  if (x < 1e-3) return 0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x * (1.0 / 120.0 - x / 720.0)));
  return (x + std::expm1(-x)) / (x * x);
}

/// A particle's flight inside one fluid step: its acceleration depends linearly on its own
/// velocity, a(v) = drive - rate v, with the gas velocity u, the drag coefficient K = m rate
/// and the pressure gradient frozen at the start of the step:
///   rate  = K / m = 1 / tau                       (1/s; 0: no drag, a ballistic flight),
///   drive = g + rate u - grad p / rho_p           (m/s^2),
/// so the velocity relaxes exponentially towards the asymptotic (terminal) velocity
/// w = drive / rate. With a0 = a(v0) the initial acceleration:
///   v(s) = v0 + a0 s phi1(rate s),   r(s) = r0 + v0 s + a0 s^2 phi2(rate s).
/// This form is exact for rate = 0 too (then it is the ballistic parabola), and has no
/// cancellation for small rate s.
struct RelaxFlight {
  double rate = 0.0;          ///< 1/tau, 1/s.
  Vec3 drive = Vec3::Zero();  ///< drive, m/s^2.

  /// The acceleration at velocity v, m/s^2.
  Vec3 acceleration(const Vec3& v) const { return drive - rate * v; }
  /// Velocity after a flight of s seconds from velocity v0, m/s.
  Vec3 velocity(const Vec3& v0, double s) const {
    return v0 + (s * relax_phi1(rate * s)) * acceleration(v0);
  }
  /// Displacement after a flight of s seconds from velocity v0, m.
  Vec3 displacement(const Vec3& v0, double s) const {
    return s * v0 + (s * s * relax_phi2(rate * s)) * acceleration(v0);
  }
  /// An upper bound of how far a flight of s >= 0 seconds from velocity v0 can carry the
  /// particle from where it starts, m: |v0| s + |a(v0)| s^2 / 2 (the acceleration only decays
  /// along the flight: a(s) = a(v0) e^{-rate s}), with each length bounded from above by the sum
  /// of its components' magnitudes (no square root). Never below the distance reached at any
  /// time in [0, s].
  double reach_bound(const Vec3& v0, double s) const {
    const Vec3 a0 = acceleration(v0);
    return s * (v0.cwiseAbs().sum() + 0.5 * s * a0.cwiseAbs().sum());
  }
  /// Moves a state (r, v) on by a flight of s seconds (exactly as displacement() and
  /// velocity() do, bit for bit) and returns the work per unit mass that the gas forces (drag
  /// and pressure gradient: the acceleration less gravity) did on the way, J/kg: the exact
  /// integral of (a(v) - g) . v over the flight. By the work-energy theorem along the exact
  /// trajectory it is the kinetic energy gained less the work of gravity,
  /// dv . (2 v0 + dv) / 2 - g . dr, computed from the increments themselves (no difference of
  /// large numbers).
  double move_booking_gas_work(Vec3& r, Vec3& v, double s, const Vec3& gravity) const {
    const Vec3 a0 = acceleration(v);
    const Vec3 dr = s * v + (s * s * relax_phi2(rate * s)) * a0;
    const Vec3 dv = (s * relax_phi1(rate * s)) * a0;
    const double work = 0.5 * dv.dot(2.0 * v + dv) - gravity.dot(dr);
    r += dr;
    v += dv;
    return work;
  }
};

/// Bounds on a set of flights (the largest drive and rate among them), so that how far any
/// particle of the set can fly is bounded from its velocity alone, without reading its flight.
struct RelaxFlightBounds {
  double drive = 0.0;  ///< The largest |drive_x| + |drive_y| + |drive_z|, m/s^2.
  double rate = 0.0;   ///< The largest rate, 1/s.

  /// Widens the bounds to hold flight f too.
  void include(const RelaxFlight& f) {
    drive = std::max(drive, f.drive.cwiseAbs().sum());
    rate = std::max(rate, f.rate);
  }
  /// Never below f.reach_bound(v0, s) for any flight f included (m): |a(v0)| is bounded by
  /// |drive| + rate |v0|, each length by the sum of its components' magnitudes.
  /// (The operations in this order are those of the batch test, reach_tests in pair_batch.hpp.)
  double reach_bound(const Vec3& v0, double s) const {
    return reach_bound_at_speed(speed_bound(v0), s);
  }
  /// The length that stands for |v0| in reach_bound: the sum of its components' magnitudes,
  /// m/s.
  static double speed_bound(const Vec3& v0) {
    return std::abs(v0.x()) + std::abs(v0.y()) + std::abs(v0.z());
  }
  /// reach_bound for a velocity whose speed_bound is `speed` (m/s). It grows with the speed and
  /// with s >= 0, computed in floating point too (each operation is monotone in its
  /// non-negative operands): a bound on the speed gives a bound on the reach.
  double reach_bound_at_speed(double speed, double s) const {
    return s * (speed + 0.5 * s * (drive + rate * speed));
  }
};

}  // namespace carom
