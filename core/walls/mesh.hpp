#pragma once
/// A mesh wall: a surface of triangles (read from STL, core/stl_reader.hpp), touched from
/// either side, each triangle a polygon wall (walls/polygon.hpp) with its exact face, edge and
/// vertex contacts. The mesh is ONE wall, not one wall per triangle:
/// - cost: the event-driven engine predicts every wall for a particle after each of its events;
///   one mesh wall first culls by the mesh's bounding box (the flight never enters it, inflated
///   by the radius: no triangle is looked at), then each triangle by its own box and by the
///   earliest contact found so far, instead of 2n + 1 quartics per triangle;
/// - shared edges: the mesh's distance is the least over its triangles, so a sphere touching an
///   edge (or vertex) shared by several triangles meets one contact, with one normal (from the
///   closest point), and bounces once; a sphere sliding over a flat face made of several
///   triangles sees one continuous distance and the face's normal across the diagonals (no
///   snag), and soft spheres keep one contact (one tangential spring) across them;
/// - labels: one name for the counters and forces of the whole mesh.
/// What one wall gives up: a soft sphere in a concave crease of ONE mesh (touching two of its
/// faces at once) feels only the closer face; give such faces as separate walls.
///
/// A `solid` mesh is a closed surface around solid material (every edge shared by exactly two
/// triangles that run along it in opposite senses); the gas cells lose the solid's volume
/// (fluid/wall_cell_cut.hpp). An open mesh (plates) takes no volume, as polygons.
#include <string>
#include <vector>

#include "core/domain.hpp"
#include "core/relax_roots.hpp"
#include "core/stl_reader.hpp"
#include "core/vec3.hpp"
#include "core/walls/polygon.hpp"

namespace carom {

/// An axis-aligned box [lower, upper], m.
struct AxisBox {
  Vec3 lower = Vec3::Constant(kNever);
  Vec3 upper = Vec3::Constant(-kNever);
  /// Grows the box to hold p.
  void add(const Vec3& p) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  /// Distance from r to the box (0 inside), m.
  double distance(const Vec3& r) const {
    return (lower - r).cwiseMax(r - upper).cwiseMax(0.0).norm();
  }
};

/// Earliest s >= 0 (s) at which the centre of a ballistic flight r + v s + g s^2 / 2 is within
/// `margin` (m) of the box on every axis at once (inside the box grown by margin); kNever if it
/// never is. Exact up to round-off of the roots (callers pad margin for it): a cull.
double ballistic_box_entry(const AxisBox& box, double margin, const Vec3& r, const Vec3& v,
                           const Vec3& g);

/// A surface of triangles, two-sided; optionally closed around solid material.
class MeshWall {
 public:
  /// The mesh of these triangles (m; see walls/polygon.hpp for each). Throws
  /// std::invalid_argument when a triangle is degenerate, or when `solid` and the surface is
  /// not closed and consistently oriented (naming the first edge that is not).
  MeshWall(std::vector<Triangle> triangles, bool solid);

  /// What keeps these triangles from being a closed, consistently oriented surface ("" when
  /// nothing): an edge (its two end points, m) held by one triangle or more than two, or by
  /// two running along it in the same sense; vertices are shared where coordinates are equal.
  static std::string closed_surface_problem(const std::vector<Triangle>& triangles);

  /// The triangles as polygon walls, in the file's order.
  const std::vector<PolygonWall>& triangles() const { return polygons_; }
  /// The triangles' vertices as given (their order: the orientation), m.
  const std::vector<Triangle>& faces() const { return faces_; }
  /// Whether the mesh is a closed surface around solid material.
  bool solid() const { return solid_; }
  /// +1 when the faces' right-handed normals point out of the solid, -1 into it (solid only).
  double orientation() const { return orientation_; }
  /// Volume enclosed by a solid mesh (0 for an open one), m^3.
  double enclosed_volume() const { return volume_; }
  /// Mean of all vertices: the apex of the tetrahedra of the volume decomposition, m.
  const Vec3& reference_point() const { return reference_; }
  /// The bounding box of all triangles, m.
  const AxisBox& bounds() const { return bounds_; }
  /// The bounding box of triangle k, m.
  const AxisBox& triangle_bounds(std::size_t k) const { return boxes_[k]; }

  /// The closest point of the surface to r (m): its distance (m) and the triangle holding it.
  struct Closest {
    Vec3 point;            ///< m
    double distance;       ///< m
    std::size_t triangle;  ///< index into triangles()
  };
  /// The closest point of the surface to r (the least over the triangles, culled by their boxes).
  Closest closest(const Vec3& r) const;

  /// Whether r lies inside the solid (solid meshes; false for open ones): the winding number
  /// of the surface about r (the sum of the triangles' signed solid angles over 4 pi) is 1
  /// inside, 0 outside; taken as inside above 1/2.
  bool inside_solid(const Vec3& r) const;

  /// Gap between a sphere (centre r, radius a) and the surface, m (> 0 apart): the distance
  /// to the surface minus a; for a sphere clear of the surface but wholly inside a solid mesh,
  /// -(distance + a) (its overlap with the solid), so that placements and checks refuse it.
  double gap(const Vec3& r, double a) const;
  /// Unit normal at the contact, from the closest point towards a sphere centred at r.
  Vec3 contact_normal(const Vec3& r) const;

  /// Earliest s >= 0 (s) at which a sphere in a ballistic flight touches the surface while
  /// approaching: the least over the triangles of PolygonWall::ballistic_contact_time, with
  /// the box culls; same conventions as the polygon's.
  double ballistic_contact_time(const Vec3& r, const Vec3& v, double a, const Vec3& g) const;
  /// Earliest s in [0, horizon] at which a sphere in a relax flight touches the surface, with
  /// the cost: the least over the triangles not farther than the flight can reach.
  RelaxContactSearch relax_contact_search(const Vec3& r, const Vec3& v, double a,
                                          const RelaxFlight& f, double horizon) const;
  /// relax_contact_search's time, s.
  double relax_contact_time(const Vec3& r, const Vec3& v, double a, const RelaxFlight& f,
                            double horizon) const {
    return relax_contact_search(r, v, a, f, horizon).time;
  }

  /// Throws std::invalid_argument (naming the wall) on a periodic axis: particles see a wall
  /// only in the domain's own copy; a mesh needs walled axes.
  void validate(const std::string& name, const Vec3& gravity, const Domain& domain) const;
  /// What `carom check` prints after the wall's name.
  std::string description() const;

 private:
  std::vector<Triangle> faces_;
  std::vector<PolygonWall> polygons_;
  std::vector<AxisBox> boxes_;
  AxisBox bounds_;
  Vec3 reference_ = Vec3::Zero();
  bool solid_ = false;
  double orientation_ = 1.0;
  double volume_ = 0.0;
};

}  // namespace carom
