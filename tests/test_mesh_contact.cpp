// The mesh wall's geometry and contact times (core/walls/mesh.hpp): the closest point against
// Ericson's closest point over all triangles; the box-entry cull against a fine scan; ballistic
// and relax contact times against the brute-force scan of the distance to the nearest
// triangle (tests/contact_oracle.hpp), for random meshes (a closed perturbed octahedron, a
// random height field) including flights aimed exactly at shared edges and vertices; a bounce
// on the shared diagonal of a flat two-triangle square happens once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "contact_oracle.hpp"
#include "core/rng.hpp"
#include "core/walls/mesh.hpp"
#include "polygon_support.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using polygon_test::closest_on_triangle;
using polygon_test::log_uniform;
using polygon_test::unit;
using test::Agreement;
using test::brute_force_contact;
using test::compare;
using test::GapFunction;
using test::Sample;

using test::kEps;

/// The closest point of the triangles to p, by Ericson over every triangle (no culls).
Vec3 oracle_closest(const std::vector<Triangle>& triangles, const Vec3& p) {
  Vec3 best = triangles[0][0];
  for (const Triangle& t : triangles) {
    const Vec3 q = closest_on_triangle(p, t[0], t[1], t[2]);
    if ((p - q).norm() < (p - best).norm()) best = q;
  }
  return best;
}

/// A random rotation applied about `centre`.
std::vector<Triangle> turned(Rng& rng, std::vector<Triangle> mesh, const Vec3& centre) {
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(rng.uniform(0.0, 6.28), unit(rng)).toRotationMatrix();
  for (Triangle& t : mesh)
    for (Vec3& p : t) p = centre + turn * (p - centre);
  return mesh;
}

/// An octahedron of size ~`size` about `centre`, its six vertices moved radially by up to 30 %:
/// a closed, outward-oriented, generally non-convex-edged solid of 8 triangles.
std::vector<Triangle> perturbed_octahedron(Rng& rng, const Vec3& centre, double size) {
  Vec3 v[6];
  const Vec3 axes[6] = {Vec3::UnitX(),  -Vec3::UnitX(), Vec3::UnitY(),
                        -Vec3::UnitY(), Vec3::UnitZ(),  -Vec3::UnitZ()};
  for (int k = 0; k < 6; ++k) v[k] = centre + size * rng.uniform(0.7, 1.3) * axes[k];
  std::vector<Triangle> mesh;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) {
        Triangle t{v[x], v[y], v[z]};
        // Outward: the right-handed normal points away from the centre.
        if ((t[1] - t[0]).cross(t[2] - t[0]).dot(t[0] - centre) < 0.0) std::swap(t[1], t[2]);
        mesh.push_back(t);
      }
  return turned(rng, mesh, centre);
}

/// A 4 x 4 height field of side `size` (32 triangles, heights up to 0.3 of the size), turned.
std::vector<Triangle> height_field(Rng& rng, const Vec3& centre, double size) {
  constexpr int n = 4;
  Vec3 p[n + 1][n + 1];
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      p[i][j] = centre +
                size * Vec3(double(i) / n - 0.5, double(j) / n - 0.5, 0.3 * rng.uniform(-0.5, 0.5));
  std::vector<Triangle> mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.push_back({p[i][j], p[i + 1][j], p[i + 1][j + 1]});
      mesh.push_back({p[i][j], p[i + 1][j + 1], p[i][j + 1]});
    }
  return turned(rng, mesh, centre);
}

TEST(MeshGeometry, ClosestPointIsTheNearestTrianglesOne) {
  Rng rng(81);
  for (int trial = 0; trial < 400; ++trial) {
    const Vec3 centre = 0.5 * rng.uniform() * unit(rng);
    const double size = log_uniform(rng, 1e-3, 1.0);
    const std::vector<Triangle> faces =
        trial % 2 ? perturbed_octahedron(rng, centre, size) : height_field(rng, centre, size);
    const MeshWall mesh(faces, false);
    for (int k = 0; k < 20; ++k) {
      const Vec3 r = centre + 2.0 * size * std::cbrt(rng.uniform()) * unit(rng);
      const Vec3 q = oracle_closest(faces, r);
      // Both round-off accurate: 1e-12 of the lengths involved.
      EXPECT_NEAR(mesh.closest(r).distance, (r - q).norm(), 1e-12 * (size + r.norm()));
    }
  }
}

TEST(MeshGeometry, BoxEntryAgreesWithAScan) {
  Rng rng(82);
  int entered = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    AxisBox box;
    box.add(0.3 * unit(rng));
    box.add(0.3 * unit(rng));
    const Vec3 r = 0.6 * unit(rng);
    // Two thirds aimed at the box's middle, the rest anywhere.
    const Vec3 aim = trial % 3 ? Vec3(0.5 * (box.lower + box.upper) - r) : unit(rng);
    const Vec3 v = log_uniform(rng, 0.1, 3.0) * aim.normalized();
    const Vec3 g =
        trial % 4 == 0 ? Vec3(Vec3::Zero()) : Vec3(log_uniform(rng, 0.01, 10.0) * unit(rng));
    const double margin = 0.02, end = 2.0;
    const double entry = ballistic_box_entry(box, margin, r, v, g);
    auto inside = [&](double s, double slack) {
      const Vec3 x = r + s * v + 0.5 * s * s * g;
      return (x.array() >= box.lower.array() - margin - slack).all() &&
             (x.array() <= box.upper.array() + margin + slack).all();
    };
    // The scan's first sample inside; the entry must come at or before it, within a step, and
    // the centre must be inside at the entry (to round-off).
    const int cells = 200000;
    double first = kNever;
    for (int i = 0; i <= cells && first == kNever; ++i)
      if (inside(end * i / cells, 0.0)) first = end * i / cells;
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    if (first != kNever) {
      ++entered;
      EXPECT_LE(entry, first);
      EXPECT_GE(entry, first - end / cells);
    }
    if (entry <= end) {
      EXPECT_TRUE(inside(entry, 1e-12)) << "entry at " << entry;
    }
  }
  std::printf("[ mesh ] box entry: %d of 2000 flights enter the box within 2 s\n", entered);
  EXPECT_GT(entered, 600);
  EXPECT_LT(entered, 1700);  // misses too
}

// --- contact times against the scan ----------------------------------------------------------

struct MeshCase {
  std::vector<Triangle> faces;
  double size;     // m
  double a;        // sphere radius, m
  Vec3 r, v;       // state at s = 0
  RelaxFlight f;   // the flight (rate 0 for ballistic ones)
  double horizon;  // s
};

GapFunction oracle_gap(const MeshCase& c) {
  return [&c](double s) {
    const Vec3 r = c.r + c.f.displacement(c.v, s), u = c.f.velocity(c.v, s);
    const Vec3 q = oracle_closest(c.faces, r);
    const double d = (r - q).norm();
    return Sample{d - c.a, d > 0.0 ? (r - q).dot(u) / d : -u.norm()};
  };
}

/// A random case: family 0 aims anywhere near the mesh; family 1 arrives at a point of a
/// shared edge (the midpoint of an edge of triangle k, its first edge: shared in both meshes
/// but for the height field's rim), family 2 at a shared vertex.
MeshCase random_case(Rng& rng, int family, bool relax) {
  for (;;) {
    MeshCase c;
    const Vec3 centre = 0.5 * rng.uniform() * unit(rng);
    c.size = log_uniform(rng, 0.01, 0.3);
    c.faces = rng.uniform() < 0.5 ? perturbed_octahedron(rng, centre, c.size)
                                  : height_field(rng, centre, c.size);
    c.a = c.size * log_uniform(rng, 0.01, 0.5);
    const Vec3 g = rng.uniform() < 0.25 ? Vec3(Vec3::Zero()) : Vec3(9.81 * unit(rng));
    c.f = RelaxFlight{relax ? log_uniform(rng, 0.1, 100.0) : 0.0, g};
    c.horizon = relax ? log_uniform(rng, 1e-4, 1e-1) : log_uniform(rng, 1e-3, 1.0);
    if (family == 0) {
      c.r = centre + 2.5 * c.size * std::cbrt(rng.uniform()) * unit(rng);
      const Vec3 aim = centre + c.size * rng.uniform() * unit(rng) - c.r;
      c.v = aim.norm() / c.horizon * log_uniform(rng, 0.3, 3.0) * aim.normalized();
    } else {
      const Triangle& t = c.faces[static_cast<std::size_t>(rng.uniform() * c.faces.size())];
      const Vec3 q = family == 1 ? Vec3(0.5 * (t[0] + t[1])) : t[0];
      const Vec3 e = unit(rng);
      const double s = rng.uniform(0.05, 1.0) * c.horizon;
      c.v = log_uniform(rng, 0.01, 3.0) * unit(rng);
      const Vec3 u = c.f.velocity(c.v, s);
      if (!(u.dot(e) < 0.0)) continue;
      // A point at distance a from q along e: it touches q's neighbourhood unless another part
      // of the mesh is nearer (then the scan decides).
      c.r = q + c.a * e - c.f.displacement(c.v, s);
    }
    if (!(oracle_gap(c)(0.0).value > 0.0)) continue;  // starts in contact
    return c;
  }
}

void check_case(Agreement& stats, const MeshCase& c, double predicted, int trial) {
  const GapFunction G = oracle_gap(c);
  const double end =
      predicted == kNever ? c.horizon : std::min(c.horizon, predicted * 1.01 + 1e-3 * c.horizon);
  const double brute = brute_force_contact(G, end, 10000);
  const double speed = std::max(c.v.norm(), c.f.velocity(c.v, c.horizon).norm());
  const double length = 2.0 * c.size + c.a + c.r.norm() + speed * c.horizon;
  const double scale = speed > 0.0 ? std::min(c.horizon, c.size / speed) : c.horizon;
  const double slope = brute == kNever ? 1.0 : std::max(std::abs(G(brute).slope), 1e-300);
  // The polygon tests' tolerance: the scan's bisection is exact, so 1e-9 of the flight's time
  // scale for the 10000-cell scan missing nothing, plus the round-off of the lengths over the
  // slope.
  compare(stats, G, predicted, brute, 1e-9 * scale + 16.0 * kEps * length / slope, c.size + c.a,
          "mesh", trial);
}

TEST(MeshBallistic, AgreesWithBruteForceScan) {
  Rng rng(83);
  Agreement stats[3];
  for (int trial = 0; trial < 1500; ++trial) {
    const MeshCase c = random_case(rng, trial % 3, false);
    const MeshWall mesh(c.faces, false);
    const double s = mesh.ballistic_contact_time(c.r, c.v, c.a, c.f.drive);
    check_case(stats[trial % 3], c, s <= c.horizon ? s : kNever, trial);
  }
  for (int f = 0; f < 3; ++f) {
    std::printf("[ mesh ] ballistic family %d: %d cases, %d contacts, worst %.2g of tolerance\n", f,
                stats[f].cases, stats[f].hits, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 100);
  }
}

TEST(MeshRelax, AgreesWithBruteForceScan) {
  Rng rng(84);
  Agreement stats[3];
  for (int trial = 0; trial < 1500; ++trial) {
    const MeshCase c = random_case(rng, trial % 3, true);
    const MeshWall mesh(c.faces, false);
    check_case(stats[trial % 3], c, mesh.relax_contact_time(c.r, c.v, c.a, c.f, c.horizon), trial);
  }
  for (int f = 0; f < 3; ++f) {
    std::printf("[ mesh ] relax family %d: %d cases, %d contacts, worst %.2g of tolerance\n", f,
                stats[f].cases, stats[f].hits, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 100);
  }
}

// A sphere falling straight onto the diagonal shared by the two triangles of a flat square:
// one contact (the time of the plane, z = a), the normal +z (the edge's closest point is right
// below), and after an elastic bounce the next contact is the return under gravity, 2 v / g
// later, not an immediate second bounce off the other triangle. References: closed forms, to
// 1e-12 relative (round-off of the roots).
TEST(MeshBallistic, ASharedEdgeIsTouchedOnce) {
  const Vec3 p00(0, 0, 0), p10(1, 0, 0), p11(1, 1, 0), p01(0, 1, 0);
  const MeshWall square({{p00, p10, p11}, {p00, p11, p01}}, false);
  const double a = 0.01, h = 0.2, g = 9.81;
  const Vec3 gravity(0, 0, -g), r(0.3, 0.3, a + h);  // (0.3, 0.3) is on the diagonal
  const double s = square.ballistic_contact_time(r, Vec3::Zero(), a, gravity);
  EXPECT_NEAR(s, std::sqrt(2 * h / g), 1e-12 * std::sqrt(2 * h / g));
  const Vec3 at = r + 0.5 * s * s * gravity;
  const Vec3 n = square.contact_normal(at);
  EXPECT_NEAR(n.z(), 1.0, 1e-15);
  const Vec3 v_in = s * gravity, v_out = v_in - 2.0 * v_in.dot(n) * n;
  const double next = square.ballistic_contact_time(at, v_out, a, gravity);
  EXPECT_NEAR(next, 2.0 * v_out.z() / g, 1e-12 * next);
}

// A solid mesh must be closed and consistently oriented: a cube's 12 triangles pass (volume
// 1, either orientation); one triangle removed, one flipped, or a triangle doubled are refused
// naming the edge.
TEST(MeshGeometry, SolidNeedsAClosedOrientedSurface) {
  std::vector<Triangle> cube;
  const auto corner = [](int i) { return Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};  // outward
  for (const auto& q : quads) {
    cube.push_back({corner(q[0]), corner(q[1]), corner(q[2])});
    cube.push_back({corner(q[0]), corner(q[2]), corner(q[3])});
  }
  const MeshWall solid(cube, true);
  EXPECT_NEAR(solid.enclosed_volume(), 1.0, 1e-15);
  EXPECT_EQ(solid.orientation(), 1.0);
  // Inside the solid (and clear of the surface) the gap is minus the overlap with the solid;
  // outside, or for an open mesh, the distance minus the radius.
  EXPECT_NEAR(solid.gap(Vec3(0.5, 0.5, 0.4), 0.1), -0.5, 1e-15);
  EXPECT_NEAR(solid.gap(Vec3(0.5, 0.5, 1.4), 0.1), 0.3, 1e-15);
  EXPECT_NEAR(solid.gap(Vec3(0.5, 0.5, 0.95), 0.1), -0.05, 1e-15);  // touching from inside
  EXPECT_NEAR(MeshWall(cube, false).gap(Vec3(0.5, 0.5, 0.4), 0.1), 0.3, 1e-15);
  std::vector<Triangle> inward = cube;
  for (Triangle& t : inward) std::swap(t[1], t[2]);
  EXPECT_EQ(MeshWall(inward, true).orientation(), -1.0);
  EXPECT_TRUE(MeshWall(inward, true).inside_solid(Vec3(0.3, 0.6, 0.2)));
  EXPECT_FALSE(MeshWall(inward, true).inside_solid(Vec3(0.3, 0.6, 1.2)));
  EXPECT_NEAR(MeshWall(inward, true).enclosed_volume(), 1.0, 1e-15);
  std::vector<Triangle> open = cube;
  open.pop_back();
  EXPECT_NE(MeshWall::closed_surface_problem(open).find("belongs to one triangle only"),
            std::string::npos);
  EXPECT_NO_THROW(MeshWall(open, false));  // an open mesh is fine as plates
  EXPECT_THROW(MeshWall(open, true), std::invalid_argument);
  std::vector<Triangle> flipped = cube;
  std::swap(flipped[3][1], flipped[3][2]);
  EXPECT_NE(MeshWall::closed_surface_problem(flipped).find("orientations disagree"),
            std::string::npos)
      << MeshWall::closed_surface_problem(flipped);
  std::vector<Triangle> doubled = cube;
  doubled.push_back(cube[0]);
  doubled.push_back({cube[0][0], cube[0][2], cube[0][1]});
  EXPECT_NE(MeshWall::closed_surface_problem(doubled).find("belongs to 4 triangles"),
            std::string::npos)
      << MeshWall::closed_surface_problem(doubled);
}

}  // namespace
}  // namespace carom
