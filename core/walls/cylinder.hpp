#pragma once
/// A cylinder wall: the inside of a circular cylinder with its axis parallel to z.
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/domain.hpp"
#include "core/relax_roots.hpp"
#include "core/roots.hpp"
#include "core/vec3.hpp"

namespace carom {

/// The inside of a cylinder of inner radius `radius` whose axis, parallel to z, passes through
/// `point` (its z is ignored); particles inside.
struct CylinderWall {
  Vec3 point = Vec3::Zero();  ///< A point on the axis (x, y used, z = 0), m.
  double radius = 0;          ///< Inner radius R, m.

  /// Gap between a sphere (centre r, radius a) and the cylinder: R - |r - axis| - a, m.
  double gap(const Vec3& r, double a) const {
    const double dx = r.x() - point.x(), dy = r.y() - point.y();
    return radius - std::sqrt(dx * dx + dy * dy) - a;
  }
  /// Unit normal at the contact, pointing from the wall towards the sphere: horizontal, towards
  /// the axis.
  Vec3 contact_normal(const Vec3& r) const {
    Vec3 n(point.x() - r.x(), point.y() - r.y(), 0.0);
    return n.normalized();
  }

  /// Earliest s >= 0 (s) at which a sphere (centre r, velocity v, radius a) in a ballistic
  /// flight touches the cylinder while moving outward; kNever if it does not. Gravity must be
  /// along the axis (validate), so the horizontal motion is linear: |d + u s|^2 = (R - a)^2.
  double ballistic_contact_time(const Vec3& r, const Vec3& v, double a, const Vec3& /*g*/) const {
    const double dx = r.x() - point.x(), dy = r.y() - point.y();
    const double reach = radius - a;
    return first_upward_crossing(v.x() * v.x() + v.y() * v.y(), 2.0 * (dx * v.x() + dy * v.y()),
                                 dx * dx + dy * dy - reach * reach);
  }
  /// Earliest s in [0, horizon] (s) at which a sphere in a relax flight f touches the cylinder
  /// (relax_cylinder_contact_time); kNever if not within the horizon.
  double relax_contact_time(const Vec3& r, const Vec3& v, double a, const RelaxFlight& f,
                            double horizon) const {
    return relax_cylinder_contact_time(r - point, v, f, radius - a, horizon);
  }

  /// Throws std::invalid_argument unless gravity is along z (the ballistic prediction needs the
  /// horizontal motion linear).
  void validate(const std::string& name, const Vec3& gravity, const Domain& /*domain*/) const {
    if (gravity.x() != 0.0 || gravity.y() != 0.0)
      throw std::invalid_argument(
          "wall '" + name + "': a cylinder's axis is along z, so gravity must be along z too");
  }
  /// What `carom check` prints after the wall's name: "cylinder R = ... m".
  std::string description() const {
    std::ostringstream out;
    out << "cylinder R = " << radius << " m, axis through (" << point.x() << ", " << point.y()
        << ")";
    return out.str();
  }
};

}  // namespace carom
