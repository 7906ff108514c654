#pragma once
/// Exact overlap volumes and areas for the porosity mapping (fluid/porosity.hpp): a sphere with
/// an axis-aligned box, a disk with a rectangle, a box with half-spaces. Closed forms, no
/// quadrature: the results are exact up to round-off (about 1e-15 of the sphere volume, disk area
/// or box volume; tests/fluid/test_porosity.cpp checks them against quadrature twins).
#include <vector>

#include "core/vec3.hpp"

namespace carom {

/// Volume of the ball |x| <= r (centred at the origin) with x >= a, y >= b, z >= c, m^3.
/// Any signs; a bound at or below -r means no bound on that axis.
double ball_corner_volume(double a, double b, double c, double r);

/// Volume of the ball (centre, radius) inside the box [lower, upper], m^3. A bound at +-infinity
/// is allowed (a half-open slab or an octant).
double sphere_box_volume(const Vec3& centre, double radius, const Vec3& lower, const Vec3& upper);

/// Area of the disk x^2 + y^2 <= R^2 with x >= a, y >= b, m^2 (any signs).
double disk_corner_area(double a, double b, double radius);

/// Area of the disk (centre (cx, cy), radius) inside the rectangle [x0, x1] x [y0, y1], m^2.
double disk_rectangle_area(double cx, double cy, double radius, double x0, double x1, double y0,
                           double y1);

/// A half-space {x : normal . x >= offset} (normal of any length > 0).
struct HalfSpace {
  Vec3 normal = Vec3::UnitZ();  ///< Points into the kept side.
  double offset = 0;            ///< normal . x on the boundary plane, m (times |normal|).
};

/// Volume of the box [lower, upper] inside all the half-spaces (convex clipping), m^3.
double box_halfspaces_volume(const Vec3& lower, const Vec3& upper,
                             const std::vector<HalfSpace>& halfspaces);

}  // namespace carom
