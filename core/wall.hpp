#pragma once
/// Fixed boundaries: a closed set of shapes (core/walls/), each shape-dependent operation a visit
/// over them, so that a new shape is one file and the compiler names every operation it lacks.
/// Shapes: infinite planes of any orientation, the inside of a vertical cylinder, the inside of
/// a vertical cone, finite convex polygons (two-sided plates), triangle meshes (from STL).
#include <string>
#include <variant>
#include <vector>

#include "domain.hpp"
#include "relax_flight.hpp"
#include "vec3.hpp"
#include "walls/cone.hpp"
#include "walls/cylinder.hpp"
#include "walls/mesh.hpp"
#include "walls/plane.hpp"
#include "walls/polygon.hpp"

namespace carom {

/// The geometry of a wall: one of the shapes of core/walls/.
using WallShape = std::variant<PlaneWall, CylinderWall, ConeWall, PolygonWall, MeshWall>;

/// A wall is a sphere of infinite mass and radius for the collision law.
struct Wall {
  std::string name;  ///< Label used for collision counters and contact laws.
  WallShape shape;   ///< Its geometry.

  /// A plane through `point` (m) whose unit normal (normalised here) points into the domain.
  static Wall plane(std::string label, const Vec3& point, const Vec3& normal) {
    return Wall{std::move(label), PlaneWall{point, normal.normalized()}};
  }
  /// The inside of a cylinder of radius `inner_radius` (m) with axis parallel to z through
  /// (axis_x, axis_y) (m).
  static Wall cylinder(std::string label, double axis_x, double axis_y, double inner_radius) {
    return Wall{std::move(label), CylinderWall{Vec3(axis_x, axis_y, 0.0), inner_radius}};
  }
  /// The inside of a cone with axis parallel to z through (axis_x, axis_y), radius
  /// radius_bottom at z_bottom and radius_top at z_top (m; see walls/cone.hpp).
  static Wall cone(std::string label, double axis_x, double axis_y, double z_bottom,
                   double radius_bottom, double z_top, double radius_top) {
    return Wall{std::move(label),
                ConeWall(axis_x, axis_y, z_bottom, radius_bottom, z_top, radius_top)};
  }

  /// The two-sided convex plate through `vertices` (m, in order around it; see
  /// walls/polygon.hpp). Throws std::invalid_argument when they are not a convex polygon.
  static Wall polygon(std::string label, std::vector<Vec3> vertices) {
    return Wall{std::move(label), PolygonWall(std::move(vertices))};
  }

  /// The surface of these triangles (m; see walls/mesh.hpp), closed around solid material when
  /// `solid`. Throws std::invalid_argument for a degenerate triangle, or a solid mesh that is
  /// not closed and consistently oriented.
  static Wall mesh(std::string label, std::vector<Triangle> triangles, bool solid) {
    return Wall{std::move(label), MeshWall(std::move(triangles), solid)};
  }

  /// Gap between a sphere (centre r, radius a) and the wall surface: > 0 when apart, m.
  double gap(const Vec3& r, double a) const {
    return std::visit([&](const auto& s) { return s.gap(r, a); }, shape);
  }
  /// Unit normal at the contact, pointing from the wall towards a sphere centred at r.
  Vec3 contact_normal(const Vec3& r) const {
    return std::visit([&](const auto& s) { return s.contact_normal(r); }, shape);
  }
  /// The shape and its dimensions in words, for `carom check` ("" for a plane).
  std::string description() const {
    return std::visit([](const auto& s) { return s.description(); }, shape);
  }
};

/// Earliest s >= 0 (s, from now) at which a sphere (centre r, m; velocity v, m/s; radius a, m)
/// in a ballistic flight under gravity g (m/s^2) touches the wall while approaching; kNever if
/// it does not. A sphere at or past contact by round-off and moving outward returns 0.
inline double ballistic_wall_contact(const Wall& wall, const Vec3& r, const Vec3& v, double a,
                                     const Vec3& g) {
  return std::visit([&](const auto& s) { return s.ballistic_contact_time(r, v, a, g); },
                    wall.shape);
}

/// Earliest s in [0, horizon] (s, from now; horizon finite, > 0) at which a sphere (centre r,
/// velocity v, radius a) in the relax flight f touches the wall; never misses a contact within
/// the horizon. kNever when it does not touch within the horizon.
inline double relax_wall_contact(const Wall& wall, const Vec3& r, const Vec3& v, double a,
                                 const RelaxFlight& f, double horizon) {
  return std::visit([&](const auto& s) { return s.relax_contact_time(r, v, a, f, horizon); },
                    wall.shape);
}

/// Throws std::invalid_argument (naming the wall) when a wall cannot be simulated under this
/// gravity (m/s^2) in this domain: a cylinder or a cone needs gravity along its axis (z), a
/// cone a walled z axis and its apex outside the domain, a polygon on a periodic axis must be
/// a strip across the period, a mesh needs walled axes.
inline void validate_walls(const std::vector<Wall>& walls, const Vec3& gravity,
                           const Domain& domain) {
  for (const Wall& wall : walls)
    std::visit([&](const auto& s) { s.validate(wall.name, gravity, domain); }, wall.shape);
}

}  // namespace carom
