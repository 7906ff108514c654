#include "scenarios/scene/walls_scene.hpp"
#include "scenarios/scene/input_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace carom {

namespace {

/// The radii x (m) of one end of a cone that keep its apex outside the domain's heights, the
/// other end's radius `other` and both heights given. `bottom`: x is radius_bottom. With
/// R(Z) (z_top - z_bottom) = radius_bottom (z_top - Z) + radius_top (Z - z_bottom), R > 0 at
/// both ends Z of the domain is linear in x there: c x + d > 0.
Range apex_free_radii(bool bottom, double other, double z_bottom, double z_top, const Domain& d,
                      const std::string& meaning) {
  Range range{0.0, std::numeric_limits<double>::infinity(), false, true, meaning};
  for (double Z : {d.lower.z(), d.upper.z()}) {
    const double c = bottom ? z_top - Z : Z - z_bottom;
    const double constant = other * (bottom ? Z - z_bottom : z_top - Z);
    if (c > 0.0 && -constant / c >= range.lower) {
      range.lower = -constant / c;
      range.lower_open = true;
    }
    if (c < 0.0 && -constant / c < range.upper) {
      range.upper = -constant / c;
      range.upper_open = true;
    }
  }
  return range;
}

/// A derived number for a message, to 6 digits (no round-off tail as 0.0037499999999999994).
std::string rounded(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}
/// A derived range for a message, its bounds to 6 digits.
std::string rounded(const Range& range) {
  return std::string(range.lower_open ? "(" : "[") + rounded(range.lower) + ", " +
         (std::isinf(range.upper) ? std::string("inf") : rounded(range.upper)) +
         (range.upper_open ? ")" : "]");
}

void read_cone(TableReader& w, const std::string& name, Scene& scene) {
  const Domain& d = scene.system.domain;
  const Vec3& g = scene.system.flight.gravity;
  if (d.periodic[2])
    w.fail("type",
           "needs a walled z axis: a cone's radius changes along z (remove \"z\" from "
           "domain.periodic)");
  if (g.x() != 0.0 || g.y() != 0.0)
    w.fail("type",
           "has its axis along z, so domain.gravity must be along z too (it has x or y parts)");
  const Vec3 axis = w.required_vector3(
      "axis", Range::any("a point on the cone's axis (along z); z is ignored, m"));
  const double z_bottom =
      w.number("z_bottom", Range::any("height of the circle of radius radius_bottom, m"));
  const double z_top =
      w.number("z_top", Range{z_bottom, std::numeric_limits<double>::infinity(), true, true,
                              "height of the circle of radius radius_top, m, above z_bottom"});
  const double radius_bottom =
      w.number("radius_bottom", Range::non_negative("inner radius at z_bottom, m"));
  const double radius_top = w.number("radius_top", Range::non_negative("inner radius at z_top, m"));
  if (!(std::max(radius_bottom, radius_top) > 0.0))
    w.fail("radius_top", "leaves no cone with radius_bottom = 0 too: one of them must be > 0");
  const ConeWall cone(axis.x(), axis.y(), z_bottom, radius_bottom, z_top, radius_top);
  if (!(cone.radius_at(d.lower.z()) > 0.0 && cone.radius_at(d.upper.z()) > 0.0)) {
    // The narrower end points at the apex: name it, with the radii that would keep the apex out.
    const bool bottom = radius_bottom < radius_top;
    const std::string key = bottom ? "radius_bottom" : "radius_top";
    const Range allowed =
        apex_free_radii(bottom, bottom ? radius_top : radius_bottom, z_bottom, z_top, d,
                        std::string("inner radius at ") + (bottom ? "z_bottom" : "z_top") +
                            ", m, that keeps the cone's apex outside the domain's heights [" +
                            format_number(d.lower.z()) + ", " + format_number(d.upper.z()) +
                            "] m with the other keys as given");
    w.fail(key, "is outside the allowed range " + rounded(allowed) + " (" + allowed.meaning +
                    ": the conical surface continues past z_bottom and z_top with the same slope, "
                    "and these radii "
                    "put its apex at z = " +
                    rounded(cone.apex_z()) + " m)");
  }
  scene.system.walls.push_back(Wall{name, cone});
}

void read_polygon(TableReader& w, const std::string& name, Scene& scene) {
  const std::vector<Vec3> vertices = w.required_vector3_list(
      "vertices", 3, Range::any("the corners of a flat convex polygon, in order around it, m"));
  if (const std::string why = PolygonWall::problem(vertices); !why.empty())
    w.fail("vertices", why +
                           " (allowed: at least 3 distinct points, in order around a convex "
                           "polygon of non-zero area, on one plane within 1e-6 of its size)");
  Wall wall = Wall::polygon(name, vertices);
  try {
    std::get<PolygonWall>(wall.shape)
        .validate(name, scene.system.flight.gravity, scene.system.domain);
  } catch (const std::invalid_argument& e) {
    w.fail("vertices", std::string("does not fit the domain: ") + e.what());
  }
  scene.system.walls.push_back(std::move(wall));
}

/// Largest STL file, bytes (a binary STL of 40 million triangles).
constexpr std::size_t kMaxStlBytes = std::size_t{2} << 30;

/// Refuses a mesh whose vertices all lie outside the domain (a wrong scale or translate).
void check_mesh_meets_domain(TableReader& w, const std::vector<Triangle>& triangles, const Domain& domain) {
  if (triangles.empty()) return;
  Vec3 low = triangles.front()[0], high = low;
  for (const Triangle& t : triangles)
    for (const Vec3& v : t) {
      low = low.cwiseMin(v);
      high = high.cwiseMax(v);
    }
  for (int a = 0; a < 3; ++a)
    if (high[a] < domain.lower[a] || low[a] > domain.upper[a])
      w.fail("file", "lies wholly outside the domain: its vertices span " + std::string(1, "xyz"[a]) + " from " +
                         format_number(low[a]) + " to " + format_number(high[a]) + " m, the domain from " +
                         format_number(domain.lower[a]) + " to " + format_number(domain.upper[a]) +
                         " m (check scale, in metres per unit of the file, and translate)");
}

/// A [[walls]] type = "mesh": the STL file (relative to the scene's folder) in metres, open or solid.
void read_mesh(TableReader& w, const std::string& name, Scene& scene) {
  const std::string written = w.required_string("file");
  if (written.empty()) w.fail("file", "must not be empty (an STL file, ASCII or binary)");
  std::filesystem::path path(written);
  if (path.is_relative()) path = std::filesystem::path(scene.file).parent_path() / path;
  StlUnits units;
  units.scale = w.number("scale", 1.0,
                         Range::positive("metres per unit of the STL file (0.001: millimetres)"));
  units.translate =
      w.vector3("translate", Vec3::Zero(), Range::any("added to every vertex after scaling, m"));
  const bool solid = w.boolean("solid", false);
  std::vector<Triangle> triangles;
  std::string bytes;
  try {
    std::error_code missing;
    if (!std::filesystem::exists(path, missing)) read_stl(path.string(), units);  // names the missing file
    bytes = read_regular_file(path.string(), "STL file", kMaxStlBytes);
  } catch (const StlError& e) {
    w.fail("file", std::string("cannot be used: ") + e.what());
  } catch (const SceneError& e) {
    w.fail("file", std::string("cannot be used: ") + e.what());
  }
  try {
    // A UTF-8 byte-order mark before "solid" (some editors write one) would make the file look binary.
    triangles = parse_stl(without_bom(std::move(bytes)), path.string(), units);
  } catch (const StlError& e) {
    w.fail("file", std::string("cannot be used: ") + shorten_long_tokens(e.what(), 40));
  }
  check_mesh_meets_domain(w, triangles, scene.system.domain);
  std::optional<Wall> wall;
  try {
    wall = Wall::mesh(name, std::move(triangles), solid);
  } catch (const std::invalid_argument& e) {
    w.fail(solid ? "solid" : "file",
           std::string("(") + path.string() + ") " + e.what() +
               (solid ? " (solid = true needs a closed surface: every edge shared by exactly two "
                        "triangles running along it in opposite senses)"
                      : ""));
  }
  try {
    std::get<MeshWall>(wall->shape)
        .validate(name, scene.system.flight.gravity, scene.system.domain);
  } catch (const std::invalid_argument& e) {
    w.fail("file", std::string("does not fit the domain: ") + e.what());
  }
  scene.system.walls.push_back(std::move(*wall));
}

}  // namespace

void read_walls(TableReader& root, Scene& scene) {
  scene.system.walls = box_walls(scene.system.domain);
  auto& materials = scene.method.soft_sphere.wall_materials;
  materials.assign(scene.system.walls.size(), std::nullopt);
  for (TableReader w : root.tables("walls")) {
    // Elastic constants for soft-sphere contacts (default: soft_sphere.wall_young_modulus, or
    // the material of the particle that touches it).
    if (w.has("young_modulus")) {
      ElasticMaterial elastic;
      elastic.young_modulus = w.number("young_modulus", Range::positive("Young's modulus of the wall, Pa (soft spheres)"));
      elastic.poisson_ratio = w.number("poisson_ratio", 0.3, Range{0.0, 0.5, false, true, "Poisson ratio of the wall (soft spheres)"});
      materials.push_back(elastic);
    } else {
      if (w.has("poisson_ratio")) w.fail("poisson_ratio", "needs young_modulus beside it");
      materials.push_back(std::nullopt);
    }
    const std::string name = w.required_string("name");
    for (const Wall& other : scene.system.walls)
      if (other.name == name)
        w.fail("name", "is already the name of a wall (box walls are x_low, x_high, y_low, ...)");
    const std::string type = w.required_string("type", {"plane", "cylinder", "cone", "polygon", "mesh"});
    if (type == "plane") {
      const Vec3 point = w.required_vector3("point", Range::any("a point on the plane, m"));
      const Vec3 normal =
          w.required_vector3("normal", Range::any("normal pointing into the particles' side"));
      if (!(normal.norm() > 0.0)) w.fail("normal", "must not be the zero vector");
      scene.system.walls.push_back(Wall::plane(name, point, normal));
    } else if (type == "cylinder") {
      const Vec3 axis = w.required_vector3(
          "axis", Range::any("a point on the cylinder's axis (along z); z is ignored, m"));
      const double radius = w.number("radius", Range::positive("inner radius of the cylinder, m"));
      scene.system.walls.push_back(Wall::cylinder(name, axis.x(), axis.y(), radius));
    } else if (type == "cone") {
      read_cone(w, name, scene);
    } else if (type == "polygon") {
      read_polygon(w, name, scene);
    } else {
      read_mesh(w, name, scene);
    }
    w.finish();
  }
}

}  // namespace carom
