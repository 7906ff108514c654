// The mesh wall's contact times: the least over its triangles (each a PolygonWall, exact), with
// box culls that only skip triangles the flight cannot touch, or not before a contact already
// found.
//
// Why the least over the triangles is the mesh's contact: the mesh's distance is the least of
// the triangles' distances; it first reaches a at the first time one of them does, and the
// triangle that does is approaching then (its distance falls to a).
//
// The box cull: a sphere touching a triangle has its centre within a of the triangle, hence
// within a of its bounding box on every axis at once. On each axis the centre's coordinate
// x(s) = r + v s + g s^2 / 2 is within the grown slab on intervals whose ends are roots of two
// quadratics; between consecutive roots (of all three axes) each axis is in or out throughout,
// so probing each piece once finds the earliest time in the grown box exactly (to round-off of
// the roots, which the callers' padding of the margin covers).
#include <algorithm>
#include <array>
#include <cmath>

#include "core/walls/mesh.hpp"

namespace carom {

namespace {

/// Padding of the culls' margin, relative to the lengths: far above the round-off of the roots
/// and of the box, far below any length that matters.
constexpr double kCullPadding = 1e-9;

/// Adds the roots s > 0 of c + b s + h s^2 = 0 to `roots` (count in `n`).
void add_positive_roots(double h, double b, double c, std::array<double, 13>& roots, int& n) {
  if (h == 0.0) {
    if (b != 0.0 && -c / b > 0.0) roots[static_cast<std::size_t>(n++)] = -c / b;
    return;
  }
  const double discriminant = b * b - 4.0 * h * c;
  if (discriminant < 0.0) return;
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  const double s1 = q / h, s2 = q != 0.0 ? c / q : 0.0;
  if (s1 > 0.0) roots[static_cast<std::size_t>(n++)] = s1;
  if (s2 > 0.0) roots[static_cast<std::size_t>(n++)] = s2;
}

}  // namespace

double ballistic_box_entry(const AxisBox& box, double margin, const Vec3& r, const Vec3& v,
                           const Vec3& g) {
  const Vec3 lower = box.lower.array() - margin, upper = box.upper.array() + margin;
  const Vec3 h = 0.5 * g;
  auto inside = [&](double s) {
    const Vec3 x = r + s * (v + s * h);
    return (x.array() >= lower.array()).all() && (x.array() <= upper.array()).all();
  };
  if (inside(0.0)) return 0.0;
  std::array<double, 13> roots{};
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    add_positive_roots(h[k], v[k], r[k] - lower[k], roots, n);
    add_positive_roots(h[k], v[k], r[k] - upper[k], roots, n);
  }
  std::sort(roots.begin(), roots.begin() + n);
  // Piece by piece: [0, roots[0]], [roots[0], roots[1]], ..., [roots[n-1], inf).
  double start = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double stop = k < n ? roots[static_cast<std::size_t>(k)] : 2.0 * start + 1.0;
    if (stop > start && inside(0.5 * (start + stop))) return start;
    if (k < n && inside(stop)) return stop;  // touches the box at one instant
    start = stop;
  }
  return kNever;
}

double MeshWall::ballistic_contact_time(const Vec3& r, const Vec3& v, double a,
                                        const Vec3& g) const {
  const double pad =
      kCullPadding * (a + (bounds_.upper - bounds_.lower).norm() + (r - bounds_.lower).norm());
  if (ballistic_box_entry(bounds_, a + pad, r, v, g) == kNever) return kNever;
  double best = kNever;
  for (std::size_t k = 0; k < polygons_.size() && best > 0.0; ++k) {
    if (!(ballistic_box_entry(boxes_[k], a + pad, r, v, g) < best)) continue;
    best = std::min(best, polygons_[k].ballistic_contact_time(r, v, a, g));
  }
  return best;
}

RelaxContactSearch MeshWall::relax_contact_search(const Vec3& r, const Vec3& v, double a,
                                                  const RelaxFlight& f, double horizon) const {
  // The velocity relaxes along a straight segment towards its terminal value, so over
  // [0, horizon] its speed is at most the larger at the ends, and the centre moves at most
  // horizon times that: triangles farther than a plus that travel cannot be touched.
  const double reach_of =
      horizon * std::max(v.norm(), f.velocity(v, horizon).norm()) * (1.0 + kCullPadding);
  const double pad =
      kCullPadding * (a + (bounds_.upper - bounds_.lower).norm() + (r - bounds_.lower).norm());
  RelaxContactSearch best{kNever, 0};
  if (bounds_.distance(r) > a + reach_of + pad) return best;
  for (std::size_t k = 0; k < polygons_.size() && best.time > 0.0; ++k) {
    if (boxes_[k].distance(r) > a + reach_of + pad) continue;
    const double limit = std::min(horizon, best.time);
    const RelaxContactSearch here = polygons_[k].relax_contact_search(r, v, a, f, limit);
    best.iterations += here.iterations;
    if (here.time < best.time) best.time = here.time;
  }
  return best;
}

}  // namespace carom
