#include "wall_cell_cut.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fluid/mesh_solid_volume.hpp"

namespace carom {

int plane_axis(const PlaneWall& wall) {
  int axis = -1;
  for (int k = 0; k < 3; ++k)
    if (std::abs(wall.normal[k]) >= 1.0 - 1e-12) axis = k;
  return axis;
}

void clip_cell(const PlaneWall& wall, CellCut& cell) {
  const int a = plane_axis(wall);
  if (a < 0) return;
  if (wall.normal[a] > 0.0)
    cell.lower[a] = std::max(cell.lower[a], wall.point[a]);
  else
    cell.upper[a] = std::min(cell.upper[a], wall.point[a]);
}

void cut_cell(const PlaneWall& wall, CellCut& cell) {
  if (plane_axis(wall) >= 0) return;
  const Vec3& lo = cell.lower;
  const Vec3& hi = cell.upper;
  const HalfSpace h{wall.normal, wall.normal.dot(wall.point)};
  double least = std::numeric_limits<double>::infinity(), most = -least;
  for (int c = 0; c < 8; ++c) {
    const Vec3 v(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z());
    const double d = h.normal.dot(v) - h.offset;
    least = std::min(least, d);
    most = std::max(most, d);
  }
  if (most <= 0.0)
    cell.outside = true;
  else if (least < 0.0)
    cell.cutting.push_back(h);
}

double inside_fraction(const CylinderWall& wall, const CellCut& cell) {
  const Vec3& lo = cell.lower;
  const Vec3& hi = cell.upper;
  const double rectangle = (hi.x() - lo.x()) * (hi.y() - lo.y());
  return disk_rectangle_area(wall.point.x(), wall.point.y(), wall.radius, lo.x(), hi.x(), lo.y(),
                             hi.y()) /
         rectangle;
}

namespace {

/// 8-point Gauss-Legendre rule on [0, 1]: nodes and weights.
constexpr std::array<double, 8> kNodes = {
    0.019855071751231856, 0.10166676129318664, 0.23723379504183550, 0.40828267875217510,
    0.59171732124782490,  0.76276620495816450, 0.89833323870681336, 0.98014492824876814};
constexpr std::array<double, 8> kWeights = {
    0.050614268145188130, 0.11119051722668724, 0.15685332293894364, 0.18134189168918099,
    0.18134189168918099,  0.15685332293894364, 0.11119051722668724, 0.050614268145188130};

/// The integral of f over [a, b] by the 8-point rule.
template <class F>
double gauss8(const F& f, double a, double b) {
  double sum = 0.0;
  for (int i = 0; i < 8; ++i) sum += kWeights[i] * f(a + (b - a) * kNodes[i]);
  return sum * (b - a);
}

/// Adaptive: the 8-point rule on [a, b] against its two halves, halving until they agree to
/// `tolerance` (absolute) or the depth runs out.
template <class F>
double adaptive(const F& f, double a, double b, double whole, double tolerance, int depth) {
  const double mid = 0.5 * (a + b);
  const double left = gauss8(f, a, mid), right = gauss8(f, mid, b);
  if (depth <= 0 || std::abs(left + right - whole) <= tolerance) return left + right;
  return adaptive(f, a, mid, left, 0.5 * tolerance, depth - 1) +
         adaptive(f, mid, b, right, 0.5 * tolerance, depth - 1);
}

}  // namespace

double inside_fraction(const ConeWall& wall, const CellCut& cell) {
  const Vec3& lo = cell.lower;
  const Vec3& hi = cell.upper;
  const double cx = wall.axis_x(), cy = wall.axis_y();
  const double rectangle = (hi.x() - lo.x()) * (hi.y() - lo.y());
  auto area_at = [&](double z) {
    return disk_rectangle_area(cx, cy, std::max(wall.radius_at(z), 0.0), lo.x(), hi.x(), lo.y(),
                               hi.y());
  };
  if (wall.slope() == 0.0) return area_at(lo.z()) / rectangle;
  // Heights where the area's form changes: the radius reaches an edge line or a corner of the
  // cross-section, or zero (the apex).
  const double a0 = lo.x() - cx, a1 = hi.x() - cx, b0 = lo.y() - cy, b1 = hi.y() - cy;
  const std::array<double, 9> radii = {0.0,
                                       std::abs(a0),
                                       std::abs(a1),
                                       std::abs(b0),
                                       std::abs(b1),
                                       std::hypot(a0, b0),
                                       std::hypot(a0, b1),
                                       std::hypot(a1, b0),
                                       std::hypot(a1, b1)};
  std::array<double, 11> cuts{};
  int n = 0;
  cuts[n++] = lo.z();
  for (double radius : radii) {
    const double z = wall.z_bottom() + (radius - wall.radius_bottom()) / wall.slope();
    if (z > lo.z() && z < hi.z()) cuts[n++] = z;
  }
  cuts[n++] = hi.z();
  std::sort(cuts.begin(), cuts.begin() + n);
  const double height = hi.z() - lo.z();
  double volume = 0.0;
  for (int k = 0; k + 1 < n; ++k) {
    const double z0 = cuts[k], dz = cuts[k + 1] - cuts[k];
    if (!(dz > 0.0)) continue;
    // z = z0 + dz (3 t^2 - 2 t^3): the (R - R_c)^{3/2} kinks at both ends become smooth in t.
    auto integrand = [&](double t) {
      return area_at(z0 + dz * t * t * (3.0 - 2.0 * t)) * 6.0 * t * (1.0 - t) * dz;
    };
    volume +=
        adaptive(integrand, 0.0, 1.0, gauss8(integrand, 0.0, 1.0), 1e-13 * rectangle * dz, 20);
  }
  return std::clamp(volume / (rectangle * height), 0.0, 1.0);
}

double inside_fraction(const MeshWall& wall, const CellCut& cell) {
  if (!wall.solid()) return 1.0;
  const double solid = mesh_solid_volume(wall, cell.lower, cell.upper, cell.cutting);
  if (solid == 0.0) return 1.0;
  const double box = cell.cutting.empty()
                         ? (cell.upper - cell.lower).prod()
                         : box_halfspaces_volume(cell.lower, cell.upper, cell.cutting);
  return box > 0.0 ? std::clamp(1.0 - solid / box, 0.0, 1.0) : 1.0;
}

}  // namespace carom
