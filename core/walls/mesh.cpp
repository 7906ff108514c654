// The mesh wall: construction, the closed-surface check, the closest point, validation.
#include "core/walls/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace carom {

namespace {

std::string point_text(const Vec3& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

}  // namespace

std::string MeshWall::closed_surface_problem(const std::vector<Triangle>& triangles) {
  // Vertices are shared where their coordinates are equal (an STL file repeats them exactly).
  std::map<std::array<double, 3>, int> index;
  std::vector<Vec3> points;
  auto id = [&](const Vec3& p) {
    const auto [it, added] =
        index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, static_cast<int>(points.size()));
    if (added) points.push_back(p);
    return it->second;
  };
  // Per undirected edge (low id, high id): the triangles running low -> high and high -> low.
  struct Uses {
    std::vector<std::size_t> forward, backward;
  };
  std::map<std::pair<int, int>, Uses> edges;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const int v[3] = {id(triangles[t][0]), id(triangles[t][1]), id(triangles[t][2])};
    for (int k = 0; k < 3; ++k) {
      const int from = v[k], to = v[(k + 1) % 3];
      Uses& uses = edges[{std::min(from, to), std::max(from, to)}];
      (from < to ? uses.forward : uses.backward).push_back(t + 1);
    }
  }
  for (const auto& [edge, uses] : edges) {
    const std::string where = "the edge from " + point_text(points[edge.first]) + " to " +
                              point_text(points[edge.second]) + " m";
    const std::size_t count = uses.forward.size() + uses.backward.size();
    const std::size_t first = uses.forward.empty() ? uses.backward[0] : uses.forward[0];
    if (count == 1)
      return where + " belongs to one triangle only (triangle " + std::to_string(first) +
             "): the surface is open there";
    if (count > 2)
      return where + " belongs to " + std::to_string(count) + " triangles (triangle " +
             std::to_string(first) + " and others): a closed surface has exactly two on each edge";
    if (uses.forward.size() != 1)
      return where + " is run along in the same sense by triangles " + std::to_string(first) +
             " and " + std::to_string(uses.forward.empty() ? uses.backward[1] : uses.forward[1]) +
             ": their orientations disagree (give every triangle's vertices in the same sense "
             "around the solid)";
  }
  return "";
}

MeshWall::MeshWall(std::vector<Triangle> triangles, bool solid)
    : faces_(std::move(triangles)), solid_(solid) {
  if (faces_.empty()) throw std::invalid_argument("the mesh has no triangles");
  Vec3 sum = Vec3::Zero();
  for (std::size_t k = 0; k < faces_.size(); ++k) {
    const Triangle& t = faces_[k];
    try {
      polygons_.emplace_back(std::vector<Vec3>(t.begin(), t.end()));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("the mesh's triangle " + std::to_string(k + 1) + ": " + e.what());
    }
    AxisBox box;
    for (const Vec3& p : t) {
      box.add(p);
      bounds_.add(p);
      sum += p;
    }
    boxes_.push_back(box);
  }
  reference_ = sum / (3.0 * static_cast<double>(faces_.size()));
  if (!solid_) return;
  if (const std::string why = closed_surface_problem(faces_); !why.empty())
    throw std::invalid_argument("the mesh is not a closed surface: " + why);
  // Signed volume of the tetrahedra (reference, face): the enclosed volume, positive when the
  // faces' right-handed normals point outward.
  double signed_volume = 0.0;
  for (const Triangle& t : faces_)
    signed_volume += (t[0] - reference_).dot((t[1] - reference_).cross(t[2] - reference_)) / 6.0;
  if (!(signed_volume != 0.0)) throw std::invalid_argument("the closed mesh encloses no volume");
  orientation_ = signed_volume > 0.0 ? 1.0 : -1.0;
  volume_ = std::abs(signed_volume);
}

MeshWall::Closest MeshWall::closest(const Vec3& r) const {
  Closest best{Vec3::Zero(), kNever, 0};
  for (std::size_t k = 0; k < polygons_.size(); ++k) {
    if (boxes_[k].distance(r) >= best.distance) continue;
    const PolygonWall::Closest c = polygons_[k].closest(r);
    if (c.distance < best.distance) best = Closest{c.point, c.distance, k};
  }
  return best;
}

bool MeshWall::inside_solid(const Vec3& r) const {
  if (!solid_ || bounds_.distance(r) > 0.0) return false;
  // Van Oosterom and Strackee's solid angle of each triangle seen from r.
  constexpr double kFourPi = 4.0 * 3.14159265358979323846;
  double angle = 0.0;
  for (const Triangle& t : faces_) {
    const Vec3 a = t[0] - r, b = t[1] - r, c = t[2] - r;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    angle += 2.0 * std::atan2(a.dot(b.cross(c)),
                              la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return orientation_ * angle / kFourPi > 0.5;
}

double MeshWall::gap(const Vec3& r, double a) const {
  const double distance = closest(r).distance;
  // Within a of the surface the sphere touches it: no need to know the side.
  if (distance < a || !inside_solid(r)) return distance - a;
  return -(distance + a);
}

Vec3 MeshWall::contact_normal(const Vec3& r) const {
  return polygons_[closest(r).triangle].contact_normal(r);
}

void MeshWall::validate(const std::string& name, const Vec3& /*gravity*/,
                        const Domain& domain) const {
  for (int k = 0; k < 3; ++k)
    if (domain.periodic[k]) {
      const std::string axis(1, "xyz"[k]);
      throw std::invalid_argument("wall '" + name + "': " + axis +
                                  " is periodic, and particles see a wall only in the domain's "
                                  "own copy, so a mesh needs walled axes (remove \"" +
                                  axis + "\" from domain.periodic)");
    }
}

std::string MeshWall::description() const {
  std::ostringstream out;
  out << "mesh of " << faces_.size() << " triangles, ";
  if (solid_)
    out << "closed around a solid of " << volume_ << " m^3, ";
  else
    out << "open (plates), ";
  out << "bounding box " << point_text(bounds_.lower) << " to " << point_text(bounds_.upper)
      << " m";
  return out.str();
}

}  // namespace carom
