#pragma once
/// Robust roots of the quadratics that ballistic predictions reduce to.
#include <cmath>

#include "vec3.hpp"

namespace carom {

/// Earliest s >= 0 at which q(s) = A s^2 + B s + C crosses zero going upward (q' > 0).
/// A state already past zero (C > 0) and still moving outward returns 0: by round-off it is
/// already across. Returns kNever when there is no such crossing.
/// In both signs of A the upward root is (-B + sqrt(B^2 - 4AC)) / (2A); it is evaluated in
/// whichever of the two algebraically equal forms has no cancellation.
inline double first_upward_crossing(double A, double B, double C) {
  if (A == 0.0) {
    if (B <= 0.0) return kNever;
    const double s = -C / B;
    return s > 0.0 ? s : 0.0;
  }
  const double discriminant = B * B - 4.0 * A * C;
  if (discriminant < 0.0) {
    // q keeps one sign; it is "outside" (and so crosses now) only if it is positive.
    return (A > 0.0 && C > 0.0) ? 0.0 : kNever;
  }
  if (discriminant == 0.0) {
    // q only touches zero at its vertex: for A < 0 it never goes above (a tangent, no
    // crossing: e.g. a particle at rest exactly on a cell face with gravity pulling it back);
    // for A > 0 it leaves zero upward at the vertex, or now if the vertex is past.
    if (A < 0.0) return kNever;
    const double vertex = -B / (2.0 * A);
    return vertex > 0.0 ? vertex : 0.0;
  }
  const double root_disc = std::sqrt(discriminant);
  double s;
  if (B <= 0.0) {
    s = (-B + root_disc) / (2.0 * A);
  } else {
    const double denominator = -B - root_disc;
    if (denominator == 0.0) return C > 0.0 ? 0.0 : kNever;
    s = 2.0 * C / denominator;
  }
  if (s >= 0.0) return s;
  // The upward crossing is in the past: q is now above zero only if we are outside.
  return (C > 0.0 && (A > 0.0 || -B / (2.0 * A) > 0.0)) ? 0.0 : kNever;
}

/// Earliest s >= 0 at which two spheres with relative position dr and relative velocity dv
/// (moving linearly relative to each other) come to the distance `contact`. Returns kNever when
/// they do not approach, or miss. Slightly overlapping approaching pairs (round-off) return 0.
inline double sphere_contact_time(const Vec3& dr, const Vec3& dv, double contact) {
  const double b = dr.dot(dv);
  if (b >= 0.0) return kNever;  // moving apart (or tangent)
  const double c = dr.squaredNorm() - contact * contact;
  if (c <= 0.0) return 0.0;  // touching or overlapping by round-off, and approaching
  const double v2 = dv.squaredNorm();
  const double discriminant = b * b - v2 * c;
  if (discriminant <= 0.0) return kNever;  // a miss (or a tangent graze, no impulse)
  return c / (-b + std::sqrt(discriminant));
}

}  // namespace carom
