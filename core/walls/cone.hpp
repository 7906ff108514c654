#pragma once
/// A cone wall: the inside of a circular cone about a vertical axis (hoppers, converging
/// ducts, spouted-bed bottoms).
///
/// The wall is the conical surface through two horizontal circles: radius radius_bottom at
/// height z_bottom and radius_top at z_top (either may be the larger one; equal radii make a
/// cylinder). Its radius varies linearly, R(z) = radius_bottom + slope (z - z_bottom), and the
/// surface continues with the same slope below z_bottom and above z_top: the two heights only
/// place it. Particles are inside (distance from the axis below R(z)). The apex, where R = 0,
/// must lie outside the domain (validate), so R > 0 wherever a particle can be.
///
/// The sphere centres of radius a that touch the surface lie on the cone offset inwards by a
/// along the normal: rho = R(z) - a / cos(alpha) (the locus), alpha the half-angle,
/// tan(alpha) = |slope|.
#include <string>

#include "core/domain.hpp"
#include "core/relax_roots.hpp"
#include "core/vec3.hpp"

namespace carom {

/// The inside of a cone about the vertical axis through (axis_x, axis_y).
class ConeWall {
 public:
  /// The cone through the circles of radius radius_bottom at z_bottom and radius_top at z_top
  /// (m). Throws std::invalid_argument unless all are finite, z_top > z_bottom, both radii
  /// >= 0 and one of them > 0.
  ConeWall(double axis_x, double axis_y, double z_bottom, double radius_bottom, double z_top,
           double radius_top);

  /// x of the axis, m.
  double axis_x() const { return axis_x_; }
  /// y of the axis, m.
  double axis_y() const { return axis_y_; }
  /// Height of the lower defining circle, m.
  double z_bottom() const { return z_bottom_; }
  /// Radius of the surface at z_bottom, m.
  double radius_bottom() const { return radius_bottom_; }
  /// Height of the upper defining circle, m.
  double z_top() const { return z_top_; }
  /// Radius of the surface at z_top, m.
  double radius_top() const { return radius_top_; }
  /// dR/dz = tan(alpha) with its sign: > 0 when the cone widens upwards (a hopper), dimensionless.
  double slope() const { return slope_; }
  /// 1 / cos(alpha) = sqrt(1 + slope^2), dimensionless.
  double secant() const { return secant_; }
  /// Height of the apex (R = 0), m; +-infinity for equal radii.
  double apex_z() const;

  /// Radius of the surface at height z, R(z) (negative past the apex), m.
  double radius_at(double z) const { return radius_bottom_ + slope_ * (z - z_bottom_); }
  /// Radius of the locus of centres of spheres of radius a touching the surface at height z,
  /// R(z) - a / cos(alpha), m.
  double locus_at(double z, double a) const { return radius_at(z) - a * secant_; }

  /// Gap between a sphere (centre r, radius a) and the surface: the distance from the centre
  /// to the surface in its meridian plane, (R(z) - rho) cos(alpha), minus a; > 0 when apart, m.
  double gap(const Vec3& r, double a) const;
  /// Unit normal at the contact, pointing from the wall towards a sphere centred at r:
  /// perpendicular to the surface in the meridian plane, (-e_rho + slope e_z) cos(alpha).
  Vec3 contact_normal(const Vec3& r) const;

  /// Earliest s >= 0 (s) at which a sphere (centre r, velocity v, radius a) in a ballistic
  /// flight under gravity g (along z, see validate) touches the surface while approaching it;
  /// kNever if it does not (or only after 1e12 s). Horizontal motion is linear and z is
  /// quadratic in s, so the contact condition rho(s)^2 = locus(z(s))^2 is a polynomial of
  /// degree 4 (2 without gravity); its roots on the other nappe (locus < 0) are not contacts.
  /// As for the plane and the cylinder: a sphere at or past contact (round-off) and moving
  /// outward returns 0; one moving inward returns its next contact, or, if it turns outward
  /// before it is back inside, the time it turns.
  double ballistic_contact_time(const Vec3& r, const Vec3& v, double a, const Vec3& g) const;

  /// Earliest s in [0, horizon] (s) at which a sphere in a relax flight f touches the surface,
  /// with the cost of the search; never misses a contact within the horizon (conservative
  /// advancement, see walls/cone_relax.cpp). kNever when it does not touch within the horizon.
  RelaxContactSearch relax_contact_search(const Vec3& r, const Vec3& v, double a,
                                          const RelaxFlight& f, double horizon) const;
  /// relax_contact_search's time, s.
  double relax_contact_time(const Vec3& r, const Vec3& v, double a, const RelaxFlight& f,
                            double horizon) const {
    return relax_contact_search(r, v, a, f, horizon).time;
  }

  /// Throws std::invalid_argument unless gravity is along z, z is not periodic and the apex
  /// lies outside the domain's z range (R > 0 on all of it).
  void validate(const std::string& name, const Vec3& gravity, const Domain& domain) const;
  /// What `carom check` prints after the wall's name: "cone R = ... m at z = ... m to ...".
  std::string description() const;

 private:
  double axis_x_, axis_y_;
  double z_bottom_, radius_bottom_, z_top_, radius_top_;
  double slope_;   // dR/dz
  double secant_;  // sqrt(1 + slope^2)
  double cosine_;  // 1 / secant
};

}  // namespace carom
