#pragma once
/// A polygon wall: a finite, flat, convex plate of zero thickness (a chute's side, a duct's
/// convergent, a baffle), touched from either side.
///
/// The plate is the convex polygon through its vertices, in order around it (either sense).
/// A sphere of radius a touches it when the distance from its centre to the closest point of
/// the plate (in the face, on an edge or at a vertex) is a; the contact normal points from that
/// point towards the centre. The distance to a convex set is a convex, once-differentiable
/// function of the centre with a unit gradient (the normal) wherever the centre is off the
/// plate, which is what the relax search (walls/polygon_relax.cpp) uses.
///
/// The closest point, from the plate's features: the face when the centre's foot on the plate's
/// plane lies inside the polygon (inside every edge's half-plane); else the closest of the
/// edges, each a segment (its line where the centre projects inside it, else an end vertex).
#include <string>
#include <vector>

#include "core/domain.hpp"
#include "core/relax_roots.hpp"
#include "core/vec3.hpp"

namespace carom {

/// A finite convex polygon, two-sided.
class PolygonWall {
 public:
  /// Relative tolerance of the vertices' plane: each may lie off the polygon's best plane by at
  /// most this fraction of the polygon's size (its largest vertex distance from the centre);
  /// they are projected onto that plane.
  static constexpr double kPlaneTolerance = 1e-6;

  /// What is wrong with these vertices (m) as a convex polygon, in words ("" when nothing):
  /// fewer than 3, a non-finite coordinate, two vertices within 1e-9 of the size of each other,
  /// a zero area (collinear), off the best plane by more than kPlaneTolerance of the size, or
  /// not convex in this order (a reflex or straight corner, or winding more than once).
  static std::string problem(const std::vector<Vec3>& vertices);

  /// The polygon through these vertices (m, in order around it). Throws std::invalid_argument
  /// with problem()'s words when they are not a convex polygon.
  explicit PolygonWall(std::vector<Vec3> vertices);

  /// The vertices, projected onto the polygon's plane, m.
  const std::vector<Vec3>& vertices() const { return vertices_; }
  /// Unit normal of the plane (Newell's, right-handed with the vertices' order).
  const Vec3& normal() const { return normal_; }
  /// Mean of the vertices (a point inside the polygon, on its plane), m.
  const Vec3& centre() const { return centre_; }
  /// Largest distance of a vertex from the centre, m.
  double size() const { return size_; }
  /// Area of the polygon, m^2.
  double area() const { return area_; }

  /// The closest point of the plate to a point r (m), with its distance (m) and which feature
  /// holds it: -1 the face, 0..n-1 edge k's interior, n..2n-1 vertex k - n.
  struct Closest {
    Vec3 point;       ///< m
    double distance;  ///< m
    int feature;      ///< face -1, edge k, vertex n + k
  };
  /// The closest point of the plate to r.
  Closest closest(const Vec3& r) const;

  /// Gap between a sphere (centre r, radius a) and the plate: distance to the closest point
  /// minus a; > 0 when apart, m.
  double gap(const Vec3& r, double a) const { return closest(r).distance - a; }
  /// Unit normal at the contact, from the closest point towards a sphere centred at r (the
  /// plane's normal, on the sphere's side, over the face; +normal() for a centre in the face).
  Vec3 contact_normal(const Vec3& r) const;

  /// Earliest s >= 0 (s) at which a sphere (centre r, velocity v, radius a) in a ballistic
  /// flight under gravity g (any direction) touches the plate while approaching it; kNever if
  /// it does not (or only after 1e12 s). Each feature's contact condition is a polynomial of
  /// degree 4 in s (2 without gravity); its earliest root at which that feature holds the
  /// closest point is taken (walls/polygon_ballistic.cpp). As for the other shapes: a sphere at or
  /// past contact (round-off) and approaching returns 0; one moving away returns its next contact,
  /// or, if it turns back before it is clear, the time it turns.
  double ballistic_contact_time(const Vec3& r, const Vec3& v, double a, const Vec3& g) const;

  /// Earliest s in [0, horizon] (s) at which a sphere in a relax flight f touches the plate,
  /// with the cost of the search; never misses a contact within the horizon (conservative
  /// advancement on the distance, see walls/polygon_relax.cpp). kNever when it does not touch
  /// within the horizon.
  RelaxContactSearch relax_contact_search(const Vec3& r, const Vec3& v, double a,
                                          const RelaxFlight& f, double horizon) const;
  /// relax_contact_search's time, s.
  double relax_contact_time(const Vec3& r, const Vec3& v, double a, const RelaxFlight& f,
                            double horizon) const {
    return relax_contact_search(r, v, a, f, horizon).time;
  }

  /// Throws std::invalid_argument unless, on each periodic axis, the polygon is a strip across
  /// the period (particles see a wall only in the domain's own copy, so anything else would be
  /// missed by particles across the periodic boundary): its plane parallel to the axis, every
  /// vertex on one of the two periodic faces, and the vertices on the upper face the lower
  /// face's moved by the period. Any gravity fits.
  void validate(const std::string& name, const Vec3& gravity, const Domain& domain) const;
  /// What `carom check` prints after the wall's name: "polygon of n vertices, area ... m^2, ...".
  std::string description() const;

 private:
  /// An edge from vertex k to vertex k + 1.
  struct Edge {
    Vec3 start;      ///< vertex k, m
    Vec3 direction;  ///< unit, towards vertex k + 1
    Vec3 outward;    ///< unit, in the plane, pointing away from the polygon
    double length;   ///< m
  };
  std::vector<Vec3> vertices_;
  std::vector<Edge> edges_;
  Vec3 normal_;
  Vec3 centre_;
  double size_;
  double area_;
};

}  // namespace carom
