#include "overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace carom {

namespace {

// --- Accurate differences of squares ------------------------------------------------------
//
// Near a tangency the closed forms below cancel large terms whose angles are sensitive to
// w = sqrt(r^2 - e^2 - z^2) when w is small. A first version with acos(e/rho), asin(z/s) and w
// recomputed at z_max erred by up to 2e-7 of the ball volume; angles are now atan2 forms of w,
// w is exact at z_max (w_a = b, w_b = a), and w^2 elsewhere comes from error-free products and
// sums, which keeps the volumes within about 1e-16 of the ball volume.

/// s + t exactly as sum + error.
void two_sum(double s, double t, double& sum, double& error) {
  sum = s + t;
  const double back = sum - s;
  error = (s - (sum - back)) + (t - back);
}

/// r^2 - e^2 - z^2 to a few ulps of the result (not of r^2).
double squares_left(double r, double e, double z) {
  const double rr = r * r, ee = e * e, zz = z * z;
  const double rr_error = std::fma(r, r, -rr), ee_error = std::fma(e, e, -ee),
               zz_error = std::fma(z, z, -zz);
  double first, first_error, second, second_error;
  two_sum(rr, -ee, first, first_error);
  two_sum(first, -zz, second, second_error);
  return second + (first_error + second_error + rr_error - ee_error - zz_error);
}

// --- Ball --------------------------------------------------------------------------------
//
// All pieces reduce to the "corner" volume V3(a, b, c) = |{x >= a, y >= b, z >= c, |x| <= r}| with
// a, b, c >= 0. Slicing at height z, the slice is a disk of radius rho = sqrt(r^2 - z^2) cut to
// x >= a, y >= b, whose area is (with X = sqrt(rho^2 - b^2), Y = sqrt(rho^2 - a^2))
//   A(z) = rho^2/2 (acos(b/rho) + acos(a/rho) - pi/2) - b X/2 - a Y/2 + a b,
// for z up to z_max = sqrt(r^2 - a^2 - b^2). Its antiderivative is closed form: by parts,
//   int (r^2 - z^2) acos(e/rho) dz = P acos(e/rho) + e int P z / (rho^2 sqrt(s^2 - z^2)) dz,
// P = r^2 z - z^3/3, s^2 = r^2 - e^2, and the last integrand splits into
// z^2/3 - 2 r^2/3 + (2 r^4/3) / (r^2 - z^2), all over sqrt(s^2 - z^2), each elementary
// (asin and atan). Collecting the terms of one edge e (a or b), with w = sqrt(s^2 - z^2),
// acos(e/rho) = atan2(w, e) and asin(z/s) = atan2(z, w):
//   T(e, z) = P acos(e/rho)/2 - e asin(z/s)(s^2 + 2 r^2)/6 - e z w/3 + (r^3/3) atan2(z e, r w),
// and V3 = [T(a, z) + T(b, z) - pi P/4 + a b z] from z = c to z_max (where w_a = b, w_b = a).

/// T(e, z) with w = sqrt(r^2 - e^2 - z^2) given.
double edge_term(double e, double z, double w, double r) {
  const double angle_e = e == 0.0 ? 0.5 * std::numbers::pi : std::atan2(w, e);
  const double angle_z = std::atan2(z, w);
  const double p = r * r * z - z * z * z / 3.0;
  return 0.5 * p * angle_e - e * angle_z * (3.0 * r * r - e * e) / 6.0 - e * z * w / 3.0 +
         r * r * r / 3.0 * std::atan2(z * e, r * w);
}

double corner_primitive(double a, double b, double z, double w_a, double w_b, double r) {
  const double p = r * r * z - z * z * z / 3.0;
  return edge_term(a, z, w_a, r) + edge_term(b, z, w_b, r) - 0.25 * std::numbers::pi * p + a * b * z;
}

/// V3(a, b, c) for a, b, c >= 0.
double positive_corner(double a, double b, double c, double r) {
  const double top2 = squares_left(r, a, b);  // z_max^2
  if (top2 <= 0.0) return 0.0;
  const double z_max = std::sqrt(top2);
  if (c >= z_max) return 0.0;
  const double w_a = std::sqrt(std::max(0.0, squares_left(r, a, c)));
  const double w_b = std::sqrt(std::max(0.0, squares_left(r, b, c)));
  return std::max(0.0,
                  corner_primitive(a, b, z_max, b, a, r) - corner_primitive(a, b, c, w_a, w_b, r));
}

double ball_volume(double r) {
  return 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

/// |{z >= c}| of the ball.
double cap_volume(double c, double r) {
  if (c >= r) return 0.0;
  if (c <= -r) return ball_volume(r);
  if (c < 0.0) return ball_volume(r) - cap_volume(-c, r);
  const double h = r - c;
  return std::numbers::pi * h * h * (2.0 * r + c) / 3.0;
}

/// |{y >= b, z >= c}| of the ball.
double wedge_volume(double b, double c, double r) {
  if (b >= r || c >= r) return 0.0;
  if (b <= -r) return cap_volume(c, r);
  if (c <= -r) return cap_volume(b, r);
  if (b < 0.0) return cap_volume(c, r) - wedge_volume(-b, c, r);
  if (c < 0.0) return cap_volume(b, r) - wedge_volume(b, -c, r);
  return 2.0 * positive_corner(0.0, b, c, r);
}

// --- Disk --------------------------------------------------------------------------------

/// |{y >= b}| of the disk of radius R.
double segment_area(double b, double radius) {
  if (b >= radius) return 0.0;
  const double full = std::numbers::pi * radius * radius;
  if (b <= -radius) return full;
  if (b < 0.0) return full - segment_area(-b, radius);
  const double x = std::sqrt((radius - b) * (radius + b));
  return radius * radius * std::atan2(x, b) - b * x;
}

// --- Convex clipping ---------------------------------------------------------------------

using Polygon = std::vector<Vec3>;

/// Clips a closed convex polyhedron (its faces) to n . x >= d; adds the cap face.
std::vector<Polygon> clip(const std::vector<Polygon>& faces, const HalfSpace& h) {
  std::vector<Polygon> kept;
  Polygon cap;
  for (const Polygon& face : faces) {
    Polygon out;
    const std::size_t m = face.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Vec3& p = face[i];
      const Vec3& q = face[(i + 1) % m];
      const double dp = h.normal.dot(p) - h.offset, dq = h.normal.dot(q) - h.offset;
      if (dp >= 0.0) out.push_back(p);
      if ((dp >= 0.0) != (dq >= 0.0)) {
        const Vec3 x = p + (q - p) * (dp / (dp - dq));
        out.push_back(x);
        cap.push_back(x);
      }
    }
    if (out.size() >= 3) kept.push_back(std::move(out));
  }
  if (cap.size() >= 3) {
    // Order the cap's points by angle about their centroid, in the plane.
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : cap) centre += x;
    centre /= static_cast<double>(cap.size());
    const Vec3 n = h.normal.normalized();
    const Vec3 u = n.unitOrthogonal(), v = n.cross(u);
    std::sort(cap.begin(), cap.end(), [&](const Vec3& x, const Vec3& y) {
      return std::atan2((x - centre).dot(v), (x - centre).dot(u)) <
             std::atan2((y - centre).dot(v), (y - centre).dot(u));
    });
    kept.push_back(std::move(cap));
  }
  return kept;
}
}  // namespace

double ball_corner_volume(double a, double b, double c, double r) {
  if (a >= r || b >= r || c >= r) return 0.0;
  if (a <= -r) return wedge_volume(b, c, r);
  if (b <= -r) return wedge_volume(a, c, r);
  if (c <= -r) return wedge_volume(a, b, r);
  if (a < 0.0) return wedge_volume(b, c, r) - ball_corner_volume(-a, b, c, r);
  if (b < 0.0) return wedge_volume(a, c, r) - ball_corner_volume(a, -b, c, r);
  if (c < 0.0) return wedge_volume(a, b, r) - ball_corner_volume(a, b, -c, r);
  return positive_corner(a, b, c, r);
}

double sphere_box_volume(const Vec3& centre, double radius, const Vec3& lower, const Vec3& upper) {
  const Vec3 lo = lower - centre, hi = upper - centre;
  if ((hi.array() <= lo.array()).any()) return 0.0;
  double volume = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const bool ux = corner & 1, uy = corner & 2, uz = corner & 4;
    const double sign = ((ux + uy + uz) % 2) ? -1.0 : 1.0;
    volume += sign * ball_corner_volume(ux ? hi.x() : lo.x(), uy ? hi.y() : lo.y(),
                                        uz ? hi.z() : lo.z(), radius);
  }
  return std::clamp(volume, 0.0, ball_volume(radius));
}

double disk_corner_area(double a, double b, double radius) {
  if (a >= radius || b >= radius) return 0.0;
  if (a <= -radius) return segment_area(b, radius);
  if (b <= -radius) return segment_area(a, radius);
  if (a < 0.0) return segment_area(b, radius) - disk_corner_area(-a, b, radius);
  if (b < 0.0) return segment_area(a, radius) - disk_corner_area(a, -b, radius);
  if (squares_left(radius, a, b) <= 0.0) return 0.0;
  // acos(b / R) = atan2(X, b) with X = sqrt(R^2 - b^2), accurate near tangency.
  const double x = std::sqrt((radius - b) * (radius + b)),
               y = std::sqrt((radius - a) * (radius + a));
  return std::max(0.0, 0.5 * radius * radius * (std::atan2(x, b) + std::atan2(y, a) - 0.5 * std::numbers::pi) -
                           0.5 * b * x - 0.5 * a * y + a * b);
}

double disk_rectangle_area(double cx, double cy, double radius, double x0, double x1, double y0,
                           double y1) {
  if (x1 <= x0 || y1 <= y0) return 0.0;
  const double a0 = x0 - cx, a1 = x1 - cx, b0 = y0 - cy, b1 = y1 - cy;
  const double area = disk_corner_area(a0, b0, radius) - disk_corner_area(a1, b0, radius) -
                      disk_corner_area(a0, b1, radius) + disk_corner_area(a1, b1, radius);
  return std::clamp(area, 0.0, (x1 - x0) * (y1 - y0));
}

double box_halfspaces_volume(const Vec3& lower, const Vec3& upper,
                             const std::vector<HalfSpace>& halfspaces) {
  if ((upper.array() <= lower.array()).any()) return 0.0;
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i)
    v[i] = Vec3(i & 1 ? upper.x() : lower.x(), i & 2 ? upper.y() : lower.y(),
                i & 4 ? upper.z() : lower.z());
  std::vector<Polygon> faces{{v[0], v[2], v[3], v[1]}, {v[4], v[5], v[7], v[6]},
                             {v[0], v[1], v[5], v[4]}, {v[2], v[6], v[7], v[3]},
                             {v[0], v[4], v[6], v[2]}, {v[1], v[3], v[7], v[5]}};
  for (const HalfSpace& h : halfspaces) {
    faces = clip(faces, h);
    if (faces.empty()) return 0.0;
  }
  // Fan tetrahedra from the vertex centroid (inside the convex polyhedron).
  Vec3 centre = Vec3::Zero();
  double count = 0.0;
  for (const Polygon& f : faces) {
    for (const Vec3& x : f) centre += x;
    count += static_cast<double>(f.size());
  }
  centre /= count;
  double volume = 0.0;
  for (const Polygon& f : faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i)
      volume += std::abs((f[0] - centre).dot((f[i] - centre).cross(f[i + 1] - centre)));
  return std::min(volume / 6.0, (upper - lower).prod());
}

}  // namespace carom
