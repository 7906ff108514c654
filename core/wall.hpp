#pragma once
/// Fixed boundaries: infinite planes of any orientation and the inside of a vertical cylinder.
#include <string>

#include "vec3.hpp"

namespace carom {

/// A wall is a sphere of infinite mass and radius for the collision law.
struct Wall {
  enum class Shape { Plane, Cylinder };
  Shape shape = Shape::Plane;
  std::string name;          ///< Label used for collision counters and contact laws.
  Vec3 point = Vec3::Zero(); ///< Plane: a point on it. Cylinder: a point on its axis (x, y used), m.
  Vec3 normal = Vec3::UnitZ();  ///< Plane: unit normal pointing into the particles' side.
  double radius = 0;         ///< Cylinder: inner radius R, m (axis along z, particles inside).

  /// A plane through `point` whose unit normal (normalised here) points into the domain.
  static Wall plane(std::string label, const Vec3& point, const Vec3& normal) {
    Wall w;
    w.shape = Shape::Plane;
    w.name = std::move(label);
    w.point = point;
    w.normal = normal.normalized();
    return w;
  }
  /// The inside of a cylinder with axis parallel to z through (axis_x, axis_y).
  static Wall cylinder(std::string label, double axis_x, double axis_y, double inner_radius) {
    Wall w;
    w.shape = Shape::Cylinder;
    w.name = std::move(label);
    w.point = Vec3(axis_x, axis_y, 0.0);
    w.radius = inner_radius;
    return w;
  }

  /// Gap between a sphere (centre r, radius a) and the wall surface: > 0 when apart, m.
  double gap(const Vec3& r, double a) const {
    if (shape == Shape::Plane) return (r - point).dot(normal) - a;
    const double dx = r.x() - point.x(), dy = r.y() - point.y();
    return radius - std::sqrt(dx * dx + dy * dy) - a;
  }
  /// Unit normal at the contact, pointing from the wall towards a sphere centred at r.
  Vec3 contact_normal(const Vec3& r) const {
    if (shape == Shape::Plane) return normal;
    Vec3 n(point.x() - r.x(), point.y() - r.y(), 0.0);
    return n.normalized();
  }
};

}  // namespace carom
