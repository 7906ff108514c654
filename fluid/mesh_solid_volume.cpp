// The solid volume of a mesh inside a cell: the signed sum of its tetrahedra's overlaps.
#include "fluid/mesh_solid_volume.hpp"

#include <algorithm>
#include <cmath>

namespace carom {

namespace {

/// The half-space of the tetrahedron's face (p, q, s) that holds its fourth vertex `opposite`.
HalfSpace face_halfspace(const Vec3& p, const Vec3& q, const Vec3& s, const Vec3& opposite) {
  Vec3 normal = (q - p).cross(s - p);
  if (normal.dot(opposite - p) < 0.0) normal = -normal;
  return HalfSpace{normal, normal.dot(p)};
}

}  // namespace

double mesh_solid_volume(const MeshWall& mesh, const Vec3& lower, const Vec3& upper,
                         const std::vector<HalfSpace>& cutting) {
  if (!mesh.solid()) return 0.0;
  const AxisBox& bounds = mesh.bounds();
  if ((bounds.upper.array() <= lower.array()).any() ||
      (bounds.lower.array() >= upper.array()).any())
    return 0.0;  // the cell misses the solid
  const Vec3& O = mesh.reference_point();
  std::vector<HalfSpace> halfspaces = cutting;
  const std::size_t first = halfspaces.size();
  halfspaces.resize(first + 4);
  double volume = 0.0;
  for (const Triangle& t : mesh.faces()) {
    const double six_volume = (t[0] - O).dot((t[1] - O).cross(t[2] - O));
    if (six_volume == 0.0) continue;  // flat: no volume
    AxisBox box;
    box.add(O);
    for (const Vec3& p : t) box.add(p);
    if ((box.upper.array() <= lower.array()).any() || (box.lower.array() >= upper.array()).any())
      continue;
    halfspaces[first] = face_halfspace(t[0], t[1], t[2], O);
    halfspaces[first + 1] = face_halfspace(O, t[0], t[1], t[2]);
    halfspaces[first + 2] = face_halfspace(O, t[1], t[2], t[0]);
    halfspaces[first + 3] = face_halfspace(O, t[2], t[0], t[1]);
    const double sign = (six_volume > 0.0 ? 1.0 : -1.0) * mesh.orientation();
    volume += sign * box_halfspaces_volume(lower, upper, halfspaces);
  }
  return std::max(volume, 0.0);
}

}  // namespace carom
