// The solid volume of a closed mesh in gas cells (fluid/mesh_solid_volume.hpp, the
// tetrahedron decomposition) against analytic volumes (a cube, an L-shaped prism: box
// intersections), against a random point-sampling estimate (the L-prism turned to a random
// orientation, cut by an oblique half-space too), and through open_volume: the cells' solid
// parts add up to the enclosed volume, an open mesh takes none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.hpp"
#include "core/wall.hpp"
#include "fluid/mesh_solid_volume.hpp"
#include "fluid/porosity.hpp"

namespace carom {
namespace {

/// Length of [a0, a1] inside [b0, b1], m.
double overlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}
/// Volume of box [lo, hi] inside box [blo, bhi], m^3.
double box_overlap(const Vec3& lo, const Vec3& hi, const Vec3& blo, const Vec3& bhi) {
  return overlap(lo.x(), hi.x(), blo.x(), bhi.x()) * overlap(lo.y(), hi.y(), blo.y(), bhi.y()) *
         overlap(lo.z(), hi.z(), blo.z(), bhi.z());
}

/// The prism over the polygon `outline` (x, y; counter-clockwise, fanned from its vertex 0,
/// which must see the whole polygon) from z = 0 to z = height, outward-oriented triangles.
std::vector<Triangle> prism(const std::vector<Vec3>& outline, double height) {
  const Vec3 up(0, 0, height);
  std::vector<Triangle> mesh;
  const std::size_t n = outline.size();
  for (std::size_t k = 1; k + 1 < n; ++k) {
    mesh.push_back({outline[0], outline[k + 1], outline[k]});                 // bottom, -z
    mesh.push_back({outline[0] + up, outline[k] + up, outline[k + 1] + up});  // top, +z
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 &p = outline[k], &q = outline[(k + 1) % n];
    mesh.push_back({p, q, q + up});
    mesh.push_back({p, q + up, p + up});
  }
  return mesh;
}

/// The L: [0, 2] x [0, 1] with [0, 1] x [1, 2] on top, 1.5 high; fanned from the reflex corner.
std::vector<Triangle> l_prism() {
  return prism(
      {Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(0, 2, 0), Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0)},
      1.5);
}
/// Whether p (in the L-prism's own frame) is inside it.
bool in_l(const Vec3& p) {
  if (p.z() < 0.0 || p.z() > 1.5 || p.x() < 0.0 || p.y() < 0.0) return false;
  return (p.x() <= 2.0 && p.y() <= 1.0) || (p.x() <= 1.0 && p.y() <= 2.0);
}
double l_volume_in_box(const Vec3& lo, const Vec3& hi) {
  return box_overlap(lo, hi, Vec3(0, 0, 0), Vec3(2, 1, 1.5)) +
         box_overlap(lo, hi, Vec3(0, 1, 0), Vec3(1, 2, 1.5));
}

// Analytic: the L-prism (non-convex) and a unit cube, in 500 random boxes (sizes 0.05-2 m,
// anywhere around them): the exact decomposition agrees to 1e-12 of the box volume plus 1e-13
// m^3 (round-off of a signed sum of up to 20 tetrahedra, each clipped exactly).
TEST(MeshSolidVolume, AgreesWithAnalyticBoxIntersections) {
  const MeshWall l(l_prism(), true);
  EXPECT_NEAR(l.enclosed_volume(), 4.5, 1e-13);
  const MeshWall cube(prism({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, 1.0),
                      true);
  EXPECT_NEAR(cube.enclosed_volume(), 1.0, 1e-14);
  Rng rng(91);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 lo(rng.uniform(-0.5, 2.2), rng.uniform(-0.5, 2.2), rng.uniform(-0.5, 1.7));
    const Vec3 hi =
        lo + Vec3(rng.uniform(0.05, 2.0), rng.uniform(0.05, 2.0), rng.uniform(0.05, 2.0));
    const double tolerance = 1e-12 * (hi - lo).prod() + 1e-13;
    EXPECT_NEAR(mesh_solid_volume(l, lo, hi, {}), l_volume_in_box(lo, hi), tolerance);
    EXPECT_NEAR(mesh_solid_volume(cube, lo, hi, {}),
                box_overlap(lo, hi, Vec3::Zero(), Vec3::Ones()), tolerance);
  }
}

// Point sampling: the L-prism turned and moved at random, a box around part of it cut by an
// oblique half-space; 200 000 uniform points in the box, each tested in the prism's own frame
// (independent of the mesh). The estimate's standard deviation is sqrt(p (1 - p) / N) of the
// box volume, at most 1.1e-3 of it: the decomposition must agree within 5 of them.
TEST(MeshSolidVolume, AgreesWithPointSamplingWhenTurnedAndCut) {
  Rng rng(92);
  for (int trial = 0; trial < 6; ++trial) {
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(rng.uniform(0.0, 6.28), rng.normal3().normalized()).toRotationMatrix();
    const Vec3 shift = rng.normal3();
    std::vector<Triangle> faces = l_prism();
    for (Triangle& t : faces)
      for (Vec3& p : t) p = turn * p + shift;
    const MeshWall mesh(faces, true);
    const Vec3 middle = turn * Vec3(0.9, 0.9, 0.75) + shift;
    const Vec3 lo = middle - Vec3::Constant(rng.uniform(0.4, 1.2)),
               hi = middle + Vec3::Constant(rng.uniform(0.4, 1.2));
    const Vec3 n = rng.normal3().normalized();
    const std::vector<HalfSpace> cut{HalfSpace{n, n.dot(middle) - 0.3}};
    const int samples = 200000;
    int hits = 0;
    for (int k = 0; k < samples; ++k) {
      const Vec3 p(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()),
                   rng.uniform(lo.z(), hi.z()));
      if (n.dot(p) >= cut[0].offset && in_l(turn.transpose() * (p - shift))) ++hits;
    }
    const double box = (hi - lo).prod(), estimate = box * hits / samples;
    const double p = double(hits) / samples;
    const double sigma = box * std::sqrt(std::max(p * (1 - p), 1.0 / samples) / samples);
    EXPECT_NEAR(mesh_solid_volume(mesh, lo, hi, cut), estimate, 5.0 * sigma) << "trial " << trial;
  }
}

// Through open_volume on a 7 x 6 x 5 grid over a box holding the turned L-prism: the cells'
// solid parts add up to the enclosed volume (1e-12 relative: a partition, exact up to
// round-off), every cell's open volume is within [0, its volume]; an open mesh (the prism
// without its top) takes nothing.
TEST(MeshSolidVolume, OpenVolumesOfAGridAddUp) {
  std::vector<Triangle> faces = l_prism();
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (Triangle& t : faces)
    for (Vec3& p : t) p = turn * p + Vec3(3, 3, 3);
  const std::vector<Wall> walls{Wall::mesh("L", faces, true)};
  const CellLayout layout{Vec3(0, 0, 0), Vec3(6, 6, 6), {7, 6, 5}};
  const std::vector<double> open = open_volume(layout, walls);
  double removed = 0.0;
  for (double v : open) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, layout.cell_volume() * (1 + 1e-12));
    removed += layout.cell_volume() - v;
  }
  EXPECT_NEAR(removed, 4.5, 1e-12 * 216.0);
  std::vector<Triangle> no_top = faces;
  no_top.erase(no_top.begin() + 1);  // a top triangle
  const std::vector<double> plates = open_volume(layout, {Wall::mesh("L", no_top, false)});
  EXPECT_EQ(plates, open_volume(layout, {}));
}

}  // namespace
}  // namespace carom
