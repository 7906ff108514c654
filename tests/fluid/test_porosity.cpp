// Porosity mapping (fluid/porosity.hpp) and its exact overlap volumes (fluid/overlap.hpp),
// against slow twins: tanh-sinh quadrature of exact slices, and Monte Carlo sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <variant>
#include <vector>

#include "fluid/overlap.hpp"
#include "fluid/porosity.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

/// Volume of the unit cube on the side n.x < offset of a plane (all n > 0), by the vertex
/// formula: sum over corners v of (-1)^|v| max(0, offset - n.v)^3 / (6 n_x n_y n_z).
double unit_cube_volume_below(const Vec3& n, double offset) {
  double below = 0.0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 v(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    const double sign = ((c & 1) + ((c >> 1) & 1) + ((c >> 2) & 1)) % 2 ? -1.0 : 1.0;
    below += sign * std::pow(std::max(0.0, offset - n.dot(v)), 3);
  }
  return below / (6.0 * n.x() * n.y() * n.z());
}


using carom::test::kPi;

/// Tanh-sinh quadrature of a bounded f over [lo, hi]: double-exponential convergence even with
/// the (x - x0)^(3/2) endpoint behaviour of the slice areas here; about 1e-15 relative with
/// step 1/64 on |t| <= 4.
template <class F>
double tanh_sinh(F f, double lo, double hi) {
  if (hi <= lo) return 0.0;
  const double half = 0.5 * (hi - lo);
  const double h = 1.0 / 64.0;
  double sum = 0.0;
  for (int k = -256; k <= 256; ++k) {
    const double t = k * h;
    const double u = 0.5 * kPi * std::sinh(t);
    const double weight = 0.5 * kPi * std::cosh(t) / (std::cosh(u) * std::cosh(u));
    // x = tanh(u), with 1 - |x| = 2 / (exp(2|u|) + 1) kept accurate near the ends.
    const double complement = 2.0 / (std::exp(2.0 * std::abs(u)) + 1.0);
    const double x = t < 0 ? lo + half * complement : hi - half * complement;
    sum += weight * f(x);
  }
  return sum * h * half;
}

/// Integrates f over [lo, hi] piecewise between the sorted breakpoints inside it.
template <class F>
double piecewise(F f, double lo, double hi, std::vector<double> breaks) {
  breaks.push_back(lo);
  breaks.push_back(hi);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = std::max(lo, breaks[i]), b = std::min(hi, breaks[i + 1]);
    if (b > a) sum += tanh_sinh(f, a, b);
  }
  return sum;
}

/// Slow twin of disk_rectangle_area: integral over x of the clipped chord length.
double disk_rectangle_area_quadrature(double cx, double cy, double r, double x0, double x1,
                                      double y0, double y1) {
  auto chord = [&](double x) {
    const double w2 = r * r - (x - cx) * (x - cx);
    if (w2 <= 0.0) return 0.0;
    const double w = std::sqrt(w2);
    return std::max(0.0, std::min(y1, cy + w) - std::max(y0, cy - w));
  };
  std::vector<double> breaks{cx - r, cx + r};
  for (double y : {y0, y1}) {
    const double e2 = r * r - (y - cy) * (y - cy);
    if (e2 > 0.0) breaks.insert(breaks.end(), {cx - std::sqrt(e2), cx + std::sqrt(e2)});
  }
  return piecewise(chord, x0, x1, breaks);
}

/// Slow twin of sphere_box_volume: integral over z of the disk-rectangle slice area, split
/// where the slice radius crosses an edge or corner distance.
double sphere_box_volume_quadrature(const Vec3& c, double r, const Vec3& lo, const Vec3& hi) {
  auto slice = [&](double z) {
    const double rho2 = r * r - (z - c.z()) * (z - c.z());
    if (rho2 <= 0.0) return 0.0;
    return disk_rectangle_area(c.x(), c.y(), std::sqrt(rho2), lo.x(), hi.x(), lo.y(), hi.y());
  };
  std::vector<double> distances2;
  for (double x : {lo.x(), hi.x()})
    for (double y : {lo.y(), hi.y()}) {
      const double dx = x - c.x(), dy = y - c.y();
      distances2.insert(distances2.end(), {dx * dx, dy * dy, dx * dx + dy * dy});
    }
  std::vector<double> breaks{c.z() - r, c.z() + r};
  for (double e2 : distances2)
    if (e2 < r * r)
      breaks.insert(breaks.end(), {c.z() - std::sqrt(r * r - e2), c.z() + std::sqrt(r * r - e2)});
  return piecewise(slice, lo.z(), hi.z(), breaks);
}

// The disk-rectangle area is exact: against the chord quadrature to 1e-13 of the disk area over
// random rectangles, and pi R^2 / 4 for a quadrant.
TEST(PorosityOverlap, DiskRectangleAreaExact) {
  EXPECT_NEAR(disk_corner_area(0.0, 0.0, 2.0), kPi, 1e-15);
  EXPECT_NEAR(disk_corner_area(-5.0, -5.0, 2.0), 4.0 * kPi, 1e-14);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  double worst = 0.0;
  for (int n = 0; n < 2000; ++n) {
    double x0 = u(rng), x1 = u(rng), y0 = u(rng), y1 = u(rng);
    if (x1 < x0) std::swap(x0, x1);
    if (y1 < y0) std::swap(y0, y1);
    const double exact = disk_rectangle_area(0.1, -0.2, 1.0, x0, x1, y0, y1);
    const double twin = disk_rectangle_area_quadrature(0.1, -0.2, 1.0, x0, x1, y0, y1);
    worst = std::max(worst, std::abs(exact - twin) / kPi);
  }
  EXPECT_LT(worst, 1e-13);
  std::printf("[ accuracy ] disk-rectangle area vs quadrature: %.1e of the disk area\n", worst);
}

// The sphere-box volume is exact: the closed-form ball-corner volume against quadrature of the
// exact slice areas, 1e-13 of the ball volume over random boxes (cells of 0.1 to 3 radii at any
// offset), plus the exact special cases (octant, cap, whole ball).
TEST(PorosityOverlap, SphereBoxVolumeExact) {
  const double r = 1.3, ball = 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(ball_corner_volume(0.0, 0.0, 0.0, r), ball / 8.0, 1e-15 * ball);
  EXPECT_NEAR(ball_corner_volume(-r, -r, 0.4, r), kPi * 0.81 * (2.6 + 0.4) / 3.0, 1e-15 * ball);
  EXPECT_NEAR(sphere_box_volume(Vec3(0.5, 0.5, 0.5), 0.2, Vec3::Zero(), Vec3::Ones()),
              4.0 / 3.0 * kPi * 0.008, 1e-17);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(sphere_box_volume(Vec3::Zero(), r, Vec3(-inf, 0.0, -inf), Vec3(inf, inf, inf)),
              ball / 2.0, 1e-15 * ball);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int n = 0; n < 500; ++n) {
    const Vec3 size = Vec3(0.1 + 2.9 * u(rng), 0.1 + 2.9 * u(rng), 0.1 + 2.9 * u(rng)) * r;
    const Vec3 lo = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * 4.0 * r - 0.5 * size;
    const double exact = sphere_box_volume(Vec3::Zero(), r, lo, lo + size);
    const double twin = sphere_box_volume_quadrature(Vec3::Zero(), r, lo, lo + size);
    worst = std::max(worst, std::abs(exact - twin) / ball);
  }
  EXPECT_LT(worst, 1e-13);
  std::printf("[ accuracy ] sphere-box volume vs quadrature: %.1e of the ball volume\n", worst);

  // Near tangency (a box corner within 1e-6 to 1e-15 radii of the sphere, inside or out), where
  // the closed form cancels large, sensitive terms: still 1e-13 of the ball volume.
  double worst_tangent = 0.0;
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int n = 0; n < 300; ++n) {
    // Some coordinates of the corner tiny (1e-2 to 1e-8 radii): the hardest case for the angles.
    Vec3 direction(gauss(rng), gauss(rng), gauss(rng));
    for (int k = 0; k < 3; ++k)
      if (u(rng) < 0.4)
        direction[k] = std::copysign(std::pow(10.0, -2.0 - 6.0 * u(rng)), direction[k]);
    direction.normalize();
    const double offset = (n % 2 ? 1.0 : -1.0) * std::pow(10.0, -6.0 - 9.0 * u(rng));
    const Vec3 corner = direction * r * (1.0 + offset);
    // The box lies on the corner's far side from the centre on each axis (the smallest piece).
    Vec3 lo, hi;
    for (int k = 0; k < 3; ++k) {
      const double extent = (0.1 + 2.0 * u(rng)) * r;
      lo[k] = corner[k] >= 0.0 ? corner[k] : corner[k] - extent;
      hi[k] = corner[k] >= 0.0 ? corner[k] + extent : corner[k];
    }
    const double exact = sphere_box_volume(Vec3::Zero(), r, lo, hi);
    const double twin = sphere_box_volume_quadrature(Vec3::Zero(), r, lo, hi);
    worst_tangent = std::max(worst_tangent, std::abs(exact - twin) / ball);
  }
  EXPECT_LT(worst_tangent, 1e-13);
  std::printf("[ accuracy ] near tangency: %.1e of the ball volume\n", worst_tangent);
}

// A cube cut by oblique planes: the convex clipping against the vertex formula
// V(n . x <= d) = sum over vertices (-1)^(upper coordinates) max(0, d - n . v)^3 / (6 nx ny nz)
// (all n > 0), and against a V-shaped pair of planes whose kept volume is 3/4 of the cube.
TEST(PorosityOverlap, BoxHalfSpacesExact) {
  const Vec3 n = Vec3(1.0, 2.0, 3.0).normalized();
  for (double d : {0.1, 0.7, 1.5, 2.9, 3.6}) {
    const double offset = d / Vec3(1.0, 2.0, 3.0).norm();
    const double below = unit_cube_volume_below(n, offset);
    const double kept = box_halfspaces_volume(Vec3::Zero(), Vec3::Ones(), {{n, offset}});
    EXPECT_NEAR(kept, 1.0 - below, 1e-14) << "d " << d;
  }
  const double v_shape = box_halfspaces_volume(Vec3::Zero(), Vec3::Ones(),
                                               {{Vec3(1, 0, 1), 0.5}, {Vec3(-1, 0, 1), -0.5}});
  EXPECT_NEAR(v_shape, 0.75, 1e-14);
  EXPECT_EQ(box_halfspaces_volume(Vec3::Zero(), Vec3::Ones(), {{Vec3(0, 0, 1), 2.0}}), 0.0);
}

struct SplitCase {
  CellLayout layout;
  std::array<bool, 3> periodic;
};

/// Monte Carlo oracle: the fraction of N uniform points of the ball landing in each cell (periodic
/// axes wrap, walled axes clamp as split_sphere does).
std::map<int, double> sample_split(const SplitCase& sc, const Vec3& centre, double r, int samples,
                                   std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 h = sc.layout.cell_size();
  std::map<int, double> counts;
  for (int s = 0; s < samples;) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (p.squaredNorm() > 1.0) continue;
    ++s;
    const Vec3 x = centre + r * p;
    std::array<int, 3> ijk;
    for (int k = 0; k < 3; ++k) {
      const int n = sc.layout.cells[k];
      int i = static_cast<int>(std::floor((x[k] - sc.layout.lower[k]) / h[k]));
      ijk[k] = sc.periodic[k] ? ((i % n) + n) % n : std::clamp(i, 0, n - 1);
    }
    counts[sc.layout.index(ijk[0], ijk[1], ijk[2])] += 1.0 / samples;
  }
  return counts;
}

// split_sphere against Monte Carlo for random spheres of 0.1 to 3 cell widths at random
// positions, across periodic boundaries and poking out of walled ones (a sphere wider than the
// periodic box overlaps itself). Sampling error: a fraction p from N = 20000 points has standard
// deviation sigma = sqrt(p (1 - p) / N) <= 0.0035; the tolerance is 6 sigma + 3 / N (the 3 / N
// covers the discreteness of counts when N p << 1), so a correct split fails with probability
// below ~1e-7 per cell, while a misplaced or missing share fails at once.
TEST(PorositySplit, MatchesMonteCarlo) {
  const SplitCase cases[] = {
      {{Vec3(0, 0, 0), Vec3(0.05, 0.04, 0.06), {5, 4, 6}}, {true, false, false}},
      {{Vec3(-1, 2, 0), Vec3(1, 2.5, 3), {4, 1, 12}}, {false, false, true}},
      {{Vec3(0, 0, 0), Vec3(1, 1, 1), {3, 3, 3}}, {true, true, true}},
  };
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int samples = 20000;
  int compared = 0;
  for (const SplitCase& sc : cases) {
    const Vec3 h = sc.layout.cell_size();
    for (int n = 0; n < 100; ++n) {
      const double r = (0.1 + 2.9 * u(rng)) * h.minCoeff() / 2.0 * (n % 3 == 0 ? 2.0 : 1.0);
      Vec3 centre;
      for (int k = 0; k < 3; ++k) {
        const double span = sc.layout.upper[k] - sc.layout.lower[k];
        // Walled axes: centres inside, spheres may poke out by up to their radius.
        centre[k] = sc.layout.lower[k] + u(rng) * span;
      }
      const std::vector<CellShare> shares = split_sphere(sc.layout, sc.periodic, centre, r);
      double sum = 0.0;
      for (const CellShare& s : shares) {
        EXPECT_GT(s.fraction, 0.0);
        sum += s.fraction;
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      std::map<int, double> exact;
      for (const CellShare& s : shares) exact[s.cell] += s.fraction;
      ASSERT_EQ(exact.size(), shares.size()) << "a cell listed twice";
      std::map<int, double> sampled = sample_split(sc, centre, r, samples, rng);
      for (const auto& [cell, p] : sampled)
        EXPECT_TRUE(exact.count(cell)) << "sampled points in cell " << cell << " missing";
      for (const auto& [cell, p] : exact) {
        const double q = sampled.count(cell) ? sampled[cell] : 0.0;
        const double sigma = std::sqrt(p * (1.0 - p) / samples);
        EXPECT_NEAR(q, p, 6.0 * sigma + 3.0 / samples) << "cell " << cell << " r " << r;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

// Total solid volume mapped equals the particles' volume to 1e-12 relative (1000 random particles
// of mixed sizes, periodic and walled axes, some poking out of the walls).
TEST(PorosityMapping, SolidVolumeConserved) {
  const CellLayout layout{Vec3(0, 0, 0), Vec3(0.04, 0.01, 0.06), {8, 2, 12}};
  const std::array<bool, 3> periodic{false, true, false};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> centres;
  std::vector<double> radii;
  double total = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double r = (0.1 + 2.9 * u(rng)) * 0.005 / 2.0;
    centres.emplace_back(0.04 * u(rng), 0.01 * u(rng), 0.06 * u(rng));
    radii.push_back(r);
    total += 4.0 / 3.0 * kPi * r * r * r;
  }
  const std::vector<double> open(layout.count(), layout.cell_volume());
  const SolidMapping m = map_solid_volume(layout, periodic, centres, radii, open, 0.3);
  double mapped = 0.0;
  for (double v : m.solid_volume) mapped += v;
  EXPECT_NEAR(mapped / total, 1.0, 1e-12);
  for (std::size_t c = 0; c < open.size(); ++c) {
    EXPECT_GE(m.porosity[c], 0.3);
    EXPECT_LE(m.porosity[c], 1.0);
    if (m.porosity[c] > 0.3) {
      EXPECT_NEAR(m.porosity[c], 1.0 - m.solid_volume[c] / open[c], 1e-15);
    }
  }
}

// Open volume of a grid cut by a vertical cylinder: each cell against the chord quadrature twin
// (1e-12 of the cell volume) and against midpoint sampling on 200 x 200 points per cell (a
// midpoint rule on an indicator errs only in sample squares the arc crosses: at most
// (arc length / delta + 4) delta^2, arc length <= the cell perimeter); the total against
// pi R^2 H to 1e-13.
TEST(PorosityOpenVolume, CylinderExact) {
  const double radius = 0.05, height = 0.3;
  const CellLayout layout{Vec3(-0.052, -0.051, 0.0), Vec3(0.053, 0.054, height), {7, 6, 3}};
  const std::vector<Wall> walls{Wall::cylinder("tube", 0.0005, 0.001, radius),
                                Wall::plane("floor", Vec3(0, 0, 0), Vec3(0, 0, 1))};
  const std::vector<double> open = open_volume(layout, walls);
  const Vec3 h = layout.cell_size();
  double total = 0.0, worst_twin = 0.0, worst_sampled = 0.0;
  const int n = 200;
  const double delta = std::max(h.x(), h.y()) / n;
  const double bound = (2.0 * (h.x() + h.y()) / delta + 4.0) * delta * delta / (h.x() * h.y());
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 7; ++i) {
        const double x0 = layout.lower.x() + i * h.x(), y0 = layout.lower.y() + j * h.y();
        const double v = open[layout.index(i, j, k)];
        total += v;
        const double twin =
            disk_rectangle_area_quadrature(0.0005, 0.001, radius, x0, x0 + h.x(), y0, y0 + h.y()) *
            h.z();
        worst_twin = std::max(worst_twin, std::abs(v - twin) / layout.cell_volume());
        int inside = 0;
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < n; ++b) {
            const double x = x0 + (a + 0.5) * h.x() / n - 0.0005;
            const double y = y0 + (b + 0.5) * h.y() / n - 0.001;
            inside += x * x + y * y <= radius * radius;
          }
        const double sampled = static_cast<double>(inside) / (n * n);
        worst_sampled = std::max(worst_sampled, std::abs(v / layout.cell_volume() - sampled));
        EXPECT_NEAR(v / layout.cell_volume(), sampled, bound);
      }
  EXPECT_LT(worst_twin, 1e-12);
  EXPECT_NEAR(total / (kPi * radius * radius * height), 1.0, 1e-13);
  std::printf("[ accuracy ] open volume: %.1e vs quadrature, %.1e vs sampling (bound %.1e)\n",
              worst_twin, worst_sampled, bound);
}

// Open volume of a grid cut by a cone (a hopper widening upwards and a duct narrowing upwards,
// the apex below or above the grid) standing on an axis-aligned floor at z = 0.02 that cuts
// through the first layer of cells. References:
//  - sampling: midpoints of n x n x nz boxes in each cell's part above the floor, inside when
//    |x - axis| <= R(z). Per z-layer the 2-D midpoint rule errs only in sample squares the
//    circle crosses (the bound of CylinderExact above); across the layers, the cross-section
//    A(z) is monotone in z (R is linear in z, the disk-rectangle area monotone in R), so the
//    midpoint rule in z errs by at most |A(top) - A(bottom)| / (2 nz) of the cross-section.
//  - the total against the frustum's volume pi h (R1^2 + R1 R2 + R2^2) / 3 between the floor
//    and the top, to 1e-12 (the grid holds the whole cone; each quadrature piece is converged
//    to 1e-13 of its box volume, and the grid's volume is about three times the cone's).
//  - equal radii: a cone that is a cylinder gives the cylinder's open volumes bit for bit.
TEST(PorosityOpenVolume, ConeAgainstSampling) {
  const CellLayout layout{Vec3(-0.052, -0.051, 0.0), Vec3(0.053, 0.054, 0.3), {7, 6, 5}};
  const double floor = 0.02, cx = 0.0005, cy = 0.001;
  const Vec3 h = layout.cell_size();
  const int n = 100, nz = 50;
  for (const auto& [r_bottom, r_top] : {std::pair{0.015, 0.05}, std::pair{0.05, 0.012}}) {
    const Wall cone = Wall::cone("hopper", cx, cy, 0.0, r_bottom, 0.3, r_top);
    const ConeWall& shape = std::get<ConeWall>(cone.shape);
    const std::vector<double> open =
        open_volume(layout, {cone, Wall::plane("floor", Vec3(0, 0, floor), Vec3(0, 0, 1))});
    double total = 0.0, worst = 0.0, worst_bound = 0.0;
    for (int k = 0; k < 5; ++k)
      for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 7; ++i) {
          const double x0 = layout.lower.x() + i * h.x(), y0 = layout.lower.y() + j * h.y();
          const double z0 = std::max(floor, k * h.z()), z1 = (k + 1) * h.z();
          const double box = h.x() * h.y() * (z1 - z0);
          const double v = open[layout.index(i, j, k)];
          total += v;
          long inside = 0;
          for (int c = 0; c < nz; ++c) {
            const double z = z0 + (c + 0.5) * (z1 - z0) / nz;
            const double R = shape.radius_at(z);
            for (int a = 0; a < n; ++a)
              for (int b = 0; b < n; ++b) {
                const double x = x0 + (a + 0.5) * h.x() / n - cx;
                const double y = y0 + (b + 0.5) * h.y() / n - cy;
                inside += x * x + y * y <= R * R;
              }
          }
          const double sampled = static_cast<double>(inside) / (double(n) * n * nz);
          const double delta = std::max(h.x(), h.y()) / n;
          const double layer =
              (2.0 * (h.x() + h.y()) / delta + 4.0) * delta * delta / (h.x() * h.y());
          const double area_bottom =
              disk_rectangle_area(cx, cy, shape.radius_at(z0), x0, x0 + h.x(), y0, y0 + h.y());
          const double area_top =
              disk_rectangle_area(cx, cy, shape.radius_at(z1), x0, x0 + h.x(), y0, y0 + h.y());
          const double bound =
              layer + std::abs(area_top - area_bottom) / (2.0 * nz * h.x() * h.y());
          worst = std::max(worst, std::abs(v / box - sampled));
          worst_bound = std::max(worst_bound, bound);
          EXPECT_NEAR(v / box, sampled, bound) << "cell " << i << " " << j << " " << k;
        }
    const double R1 = shape.radius_at(floor), R2 = shape.radius_at(0.3);
    const double frustum = kPi * (0.3 - floor) * (R1 * R1 + R1 * R2 + R2 * R2) / 3.0;
    EXPECT_NEAR(total / frustum, 1.0, 1e-12);
    std::printf(
        "[ accuracy ] cone open volume: total %.1e vs the frustum, %.1e vs sampling "
        "(bound %.1e)\n",
        total / frustum - 1.0, worst, worst_bound);
  }
  const std::vector<double> as_cone =
      open_volume(layout, {Wall::cone("tube", cx, cy, 0.0, 0.05, 0.3, 0.05)});
  const std::vector<double> as_cylinder =
      open_volume(layout, {Wall::cylinder("tube", cx, cy, 0.05)});
  for (std::size_t c = 0; c < as_cone.size(); ++c) EXPECT_EQ(as_cone[c], as_cylinder[c]);
}

// Planes: an axis-aligned floor clips cells exactly, an oblique plane by convex clipping; the
// total is the box's volume on the kept side (vertex formula as above).
TEST(PorosityOpenVolume, PlanesExact) {
  const CellLayout layout{Vec3(0, 0, 0), Vec3(1, 1, 1), {4, 4, 4}};
  const std::vector<double> floor_cut =
      open_volume(layout, {Wall::plane("floor", Vec3(0, 0, 0.3), Vec3(0, 0, 1))});
  for (int k = 0; k < 4; ++k) {
    const double expected = std::clamp(0.25 * (k + 1) - 0.3, 0.0, 0.25) * 0.0625;
    EXPECT_NEAR(floor_cut[layout.index(1, 2, k)], expected, 1e-17);
  }
  const Vec3 n = Vec3(1.0, 2.0, 3.0).normalized();
  const double offset = 2.2 / Vec3(1.0, 2.0, 3.0).norm();
  const std::vector<double> oblique = open_volume(layout, {Wall::plane("slope", n * offset, n)});
  double total = 0.0;
  for (double v : oblique) total += v;
  const double below = unit_cube_volume_below(n, offset);
  EXPECT_NEAR(total, 1.0 - below, 1e-14);
}

// Cells outside the walls get eps = 1; an overfull cell is floored and counted.
TEST(PorosityMapping, FloorAndClosedCells) {
  const CellLayout layout{Vec3(-1, -1, 0), Vec3(1, 1, 1), {4, 4, 1}};
  const std::vector<double> open = open_volume(layout, {Wall::cylinder("tube", 0, 0, 0.45)});
  EXPECT_EQ(open[layout.index(0, 0, 0)], 0.0);  // corner cell: wholly outside the tube
  const std::vector<Vec3> centres{Vec3(-0.25, -0.25, 0.5), Vec3(-0.25, -0.25, 0.5)};
  const std::vector<double> radii{0.25, 0.25};  // two overlapping spheres: 2 x 0.06545 m^3
  const SolidMapping m = map_solid_volume(layout, {false, false, false}, centres, radii, open, 0.3);
  EXPECT_EQ(m.porosity[layout.index(0, 0, 0)], 1.0);
  // Open: a quarter disk, pi 0.45^2 / 4 = 0.15904 m^3; solid 0.1309 m^3: 1 - solid/open = 0.18.
  EXPECT_EQ(m.porosity[layout.index(1, 1, 0)], 0.3);
  EXPECT_EQ(m.floored_cells, 1);
}

// A sphere across one face takes split_sphere's shortcut (two ball-corner volumes instead of the
// twelve nodes of its two cells): the same cells and the same bits as the split by every node,
// for random spheres of 0.02 to 1.2 cell widths on walled and periodic grids (one of them a
// single periodic cell deep, as in a pseudo-2-D bed, where a sphere across its periodic face is
// split into two pieces of one cell), and for spheres whose side lies on a face to round-off.
TEST(PorositySplit, ShortcutAcrossOneFaceGivesTheSplitByEveryNodeBitForBit) {
  struct Grid {
    CellLayout layout;
    std::array<bool, 3> periodic;
  };
  const Grid grids[] = {
      {{Vec3(0, 0, 0), Vec3(0.04, 0.004, 0.1), {10, 1, 25}}, {false, true, false}},
      {{Vec3(-1, -2, 0.5), Vec3(1, 1, 2), {7, 5, 4}}, {true, false, true}},
      {{Vec3(0, 0, 0), Vec3(1, 1, 1), {6, 6, 6}}, {false, false, false}}};
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int one_face = 0;
  for (const Grid& g : grids) {
    const Vec3 size = g.layout.upper - g.layout.lower, h = g.layout.cell_size();
    for (int n = 0; n < 20000; ++n) {
      const double radius = (0.02 + 1.18 * unit(rng) * unit(rng)) * h.minCoeff();
      Vec3 centre = g.layout.lower + size.cwiseProduct(Vec3(unit(rng), unit(rng), unit(rng)));
      if (n % 2 == 0) {  // a side on a face, to a few units in the last place
        const int k = n / 2 % 3;
        const double face =
            g.layout.lower[k] + h[k] * std::round((centre[k] - g.layout.lower[k]) / h[k]);
        centre[k] = n % 4 == 0 ? face - radius : face + radius;
        for (int step = static_cast<int>(7 * unit(rng)) - 3; step != 0; step += step > 0 ? -1 : 1)
          centre[k] = std::nextafter(centre[k], step > 0 ? 1e300 : -1e300);
      }
      std::vector<CellShare> fast, oracle;
      split_sphere(g.layout, g.periodic, centre, radius, fast);
      detail::split_sphere_by_corners(g.layout, g.periodic, centre, radius, oracle);
      ASSERT_EQ(fast.size(), oracle.size()) << n;
      for (std::size_t i = 0; i < fast.size(); ++i) {
        ASSERT_EQ(fast[i].cell, oracle[i].cell) << n;
        ASSERT_EQ(std::bit_cast<std::uint64_t>(fast[i].fraction),
                  std::bit_cast<std::uint64_t>(oracle[i].fraction))
            << n << " centre " << centre.transpose() << " radius " << radius;
      }
      if (fast.size() == 2) ++one_face;
    }
  }
  EXPECT_GT(one_face, 10000);  // the shortcut's case is common here, not a corner case
}

// Cost of split_sphere per particle (printed, not asserted: machine-dependent). The coupling
// splits every particle once per fluid step.
// The early-outs of split_sphere: a small sphere inside one cell touches one cell, one
// across a face two, one at a grid node eight (timings are measured outside the test suite:
// 0.05 us, 0.08 us and 0.9 us per call on the development machine).
TEST(PorositySplit, CellCountsOfTypicalSpheres) {
  const CellLayout layout{Vec3(0, 0, 0), Vec3(1, 1, 1), {10, 10, 10}};
  const std::array<bool, 3> periodic{true, true, true};
  EXPECT_EQ(split_sphere(layout, periodic, Vec3(0.25, 0.35, 0.45), 0.02).size(), 1u);
  EXPECT_EQ(split_sphere(layout, periodic, Vec3(0.5 + 1e-3, 0.55, 0.55), 0.02).size(), 2u);
  EXPECT_EQ(split_sphere(layout, periodic, Vec3(0.5 + 1e-3, 0.5 - 2e-3, 0.5 + 3e-3), 0.02).size(), 8u);
}

}  // namespace
}  // namespace carom
