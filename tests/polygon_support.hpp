#pragma once
// Shared by the polygon wall tests: random convex polygons and an independent closest point
// (Ericson's closest point on a triangle, over a fan of triangles), the oracle of the
// distance.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.hpp"
#include "core/vec3.hpp"
#include "tests/random_draws.hpp"

namespace carom::polygon_test {

using test::log_uniform;
using test::unit;

/// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5): by the
/// Voronoi regions of the vertices, edges and face, from barycentric coordinates.
inline Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

/// Closest point of the convex polygon (vertices in order) to p: the closest of the fan's
/// triangles' closest points.
inline Vec3 oracle_closest(const std::vector<Vec3>& polygon, const Vec3& p) {
  Vec3 best = polygon[0];
  double best_distance = (p - best).norm();
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const Vec3 q = closest_on_triangle(p, polygon[0], polygon[k], polygon[k + 1]);
    const double d = (p - q).norm();
    if (d < best_distance) {
      best_distance = d;
      best = q;
    }
  }
  return best;
}

/// A random convex polygon: n = 3..8 corners at sorted random angles on an ellipse (axes
/// `size` and 0.3..1 of it), turned to a random orientation about a random centre (within
/// 0.5 m of the origin). The corners' angles are at least 0.05 rad apart.
inline std::vector<Vec3> random_polygon(Rng& rng, double size) {
  const int n = 3 + static_cast<int>(rng.uniform() * 6.0);
  std::vector<double> angles;
  while (static_cast<int>(angles.size()) < n) {
    const double t = rng.uniform(0.0, 6.283185307179586);
    bool apart = true;
    for (double u : angles) {
      const double d = std::abs(t - u);
      apart = apart && std::min(d, 6.283185307179586 - d) > 0.05;
    }
    if (apart) angles.push_back(t);
  }
  std::sort(angles.begin(), angles.end());
  const double minor = size * rng.uniform(0.3, 1.0);
  const Vec3 e1 = unit(rng);
  const Vec3 e2 = e1.cross(unit(rng)).normalized();
  const Vec3 centre = 0.5 * rng.uniform() * unit(rng);
  std::vector<Vec3> out;
  for (double t : angles)
    out.push_back(centre + size * std::cos(t) * e1 + minor * std::sin(t) * e2);
  if (rng.uniform() < 0.5) std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace carom::polygon_test
