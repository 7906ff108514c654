#pragma once
/// A plane wall: an infinite plane of any orientation, particles on the side its normal points to.
#include <string>

#include "core/domain.hpp"
#include "core/relax_roots.hpp"
#include "core/roots.hpp"
#include "core/vec3.hpp"

namespace carom {

/// An infinite plane through `point` whose unit normal points into the particles' side.
struct PlaneWall {
  Vec3 point = Vec3::Zero();    ///< A point on the plane, m.
  Vec3 normal = Vec3::UnitZ();  ///< Unit normal pointing into the particles' side.

  /// Gap between a sphere (centre r, radius a) and the plane: > 0 when apart, m.
  double gap(const Vec3& r, double a) const { return (r - point).dot(normal) - a; }
  /// Unit normal at the contact, pointing from the wall towards the sphere: the plane's normal.
  Vec3 contact_normal(const Vec3& /*r*/) const { return normal; }

  /// Earliest s >= 0 (s) at which a sphere (centre r, velocity v, radius a) in a ballistic
  /// flight under gravity g touches the plane while approaching; kNever if it does not.
  /// The gap h(s) = h0 + (v.n) s + (g.n) s^2/2; contact when h falls through zero.
  double ballistic_contact_time(const Vec3& r, const Vec3& v, double a, const Vec3& g) const {
    const double gap = (r - point).dot(normal) - a;
    return first_upward_crossing(-0.5 * g.dot(normal), -v.dot(normal), -gap);
  }
  /// Earliest s in [0, horizon] (s) at which a sphere in a relax flight f touches the plane
  /// (relax_gap_closing_time along the normal); kNever if not within the horizon.
  double relax_contact_time(const Vec3& r, const Vec3& v, double a, const RelaxFlight& f,
                            double horizon) const {
    const double gap = (r - point).dot(normal) - a;
    return relax_gap_closing_time(gap, v.dot(normal), f.drive.dot(normal), f.rate, horizon);
  }

  /// A plane fits any gravity and any box: nothing to check.
  void validate(const std::string& /*name*/, const Vec3& /*gravity*/,
                const Domain& /*domain*/) const {}
  /// What `carom check` prints after the wall's name: nothing (box walls are planes).
  std::string description() const { return ""; }
};

}  // namespace carom
