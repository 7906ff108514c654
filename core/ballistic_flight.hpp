#pragma once
/// The `ballistic` flight model: free flight under uniform gravity between events.
#include "vec3.hpp"

namespace carom {

/// r(s) = r0 + v0 s + g s^2 / 2,  v(s) = v0 + g s. Spin is constant in flight.
struct BallisticFlight {
  Vec3 gravity = Vec3::Zero();  ///< g, m/s^2.

  Vec3 position(const Vec3& r0, const Vec3& v0, double s) const {
    return r0 + s * v0 + (0.5 * s * s) * gravity;
  }
  Vec3 velocity(const Vec3& v0, double s) const { return v0 + s * gravity; }
  bool has_gravity() const { return gravity.x() != 0.0 || gravity.y() != 0.0 || gravity.z() != 0.0; }
  /// The vertical axis: the one gravity acts along most strongly (0 x, 1 y, 2 z; z without gravity).
  int vertical_axis() const {
    int axis = 2;
    if (!has_gravity()) return axis;
    axis = 0;
    for (int k = 1; k < 3; ++k)
      if (gravity[k] * gravity[k] > gravity[axis] * gravity[axis]) axis = k;
    return axis;
  }
};

}  // namespace carom
