// The polygon wall (core/walls/polygon.hpp): the distance and normal against an independent
// closest point (Ericson's, over a fan of triangles: tests/polygon_support.hpp) and a fine
// sampling of the polygon, two sides, the vertex checks, the periodic-axis rule.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/wall.hpp"
#include "polygon_support.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using polygon_test::log_uniform;
using polygon_test::oracle_closest;
using polygon_test::random_polygon;
using polygon_test::unit;

using carom::test::kGravityVector;

// The gap against the oracle's distance (to 1e-14 of the lengths: a few roundings) and against
// a fine sampling of the polygon (a triangular grid of 150 x 150 per fan triangle: the sampled
// distance is above the true one by at most the grid's cell diameter, and never below it by
// more than round-off); the normal against the oracle's direction (unit, to 1e-12: the centre
// is at least 1e-3 of the size away, so round-off of the closest point turns it by < 1e-12).
TEST(PolygonGeometry, GapAndNormalAgreeWithTheOracleAndASampling) {
  Rng rng(71);
  for (int trial = 0; trial < 60; ++trial) {
    const double size = log_uniform(rng, 0.01, 1.0);
    const std::vector<Vec3> corners = random_polygon(rng, size);
    const PolygonWall plate(corners);
    const std::vector<Vec3>& p = plate.vertices();
    const double a = size * log_uniform(rng, 1e-3, 0.5);
    // Points near the plate: above the face, beside edges and corners, in the plane.
    Vec3 r = plate.centre() + size * rng.uniform(0.0, 1.6) * unit(rng);
    if (trial % 4 == 0) r -= (r - plate.centre()).dot(plate.normal()) * plate.normal();
    const Vec3 q = oracle_closest(p, r);
    const double distance = (r - q).norm();
    if (!(distance > 1e-3 * size)) continue;
    const double length = (r - plate.centre()).norm() + size + plate.centre().norm();
    EXPECT_NEAR(plate.gap(r, a), distance - a, 1e-14 * length) << "trial " << trial;
    const Vec3 n = plate.contact_normal(r);
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    EXPECT_LE((n - (r - q) / distance).norm(), 1e-12) << "trial " << trial;
    double sampled = kNever, cell = 0.0;
    const int N = 150;
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      const Vec3 A = p[0], B = p[k], C = p[k + 1];
      cell = std::max({cell, (B - A).norm() / N, (C - A).norm() / N, (C - B).norm() / N});
      for (int i = 0; i <= N; ++i)
        for (int j = 0; i + j <= N; ++j)
          sampled = std::min(
              sampled, (r - (A + (B - A) * (double(i) / N) + (C - A) * (double(j) / N))).norm());
    }
    EXPECT_GE(sampled, distance - 1e-14 * length);
    EXPECT_LE(sampled, distance + cell);
  }
}

// Both sides: the normal points to the sphere's side over the face, the gap is symmetric.
TEST(PolygonGeometry, TwoSided) {
  const PolygonWall plate({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
  EXPECT_EQ(plate.contact_normal(Vec3(0.5, 0.5, 0.2)), Vec3(0, 0, 1));
  EXPECT_EQ(plate.contact_normal(Vec3(0.5, 0.5, -0.2)), Vec3(0, 0, -1));
  EXPECT_DOUBLE_EQ(plate.gap(Vec3(0.5, 0.5, -0.2), 0.1), 0.1);
  EXPECT_DOUBLE_EQ(plate.gap(Vec3(1.3, 0.5, 0.4), 0.1), 0.4);  // beside an edge
  EXPECT_DOUBLE_EQ(plate.gap(Vec3(1.3, 1.4, 0.0), 0.1), 0.4);  // beside a corner
  EXPECT_DOUBLE_EQ(plate.area(), 1.0);
}

// Bad vertex lists: each problem named.
TEST(PolygonGeometry, ChecksItsVertices) {
  auto problem = [](const std::vector<Vec3>& v) { return PolygonWall::problem(v); };
  auto has = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  EXPECT_EQ(problem({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), "");
  EXPECT_TRUE(has(problem({Vec3(0, 0, 0), Vec3(1, 0, 0)}), "at least 3"));
  EXPECT_TRUE(has(problem({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}),
                  "vertices 2 and 3 coincide"));
  EXPECT_TRUE(has(problem({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)}), "no area"));
  EXPECT_TRUE(
      has(problem({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1e-3), Vec3(0, 1, 0)}), "is not flat"));
  EXPECT_EQ(problem({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1e-8), Vec3(0, 1, 0)}), "")
      << "off the plane by 1e-8 of the size: projected";
  EXPECT_TRUE(
      has(problem({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.2, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}),
          "not convex"));
  EXPECT_TRUE(has(problem({Vec3(0, 0, 0), Vec3(3, 1, 0), Vec3(3, 0, 0), Vec3(0, 2, 0)}),
                  "not convex"));  // a bow tie: corners out of order
  EXPECT_TRUE(
      has(problem({Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), "straight"));
  std::vector<Vec3> star;
  for (int k = 0; k < 5; ++k) {
    const double t = 2.0 * 6.283185307179586 * k / 5;
    star.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  EXPECT_TRUE(has(problem(star), "more than once"));
  EXPECT_THROW(PolygonWall({Vec3(0, 0, 0), Vec3(1, 0, 0)}), std::invalid_argument);
}

// On a periodic axis only a strip across the period is allowed.
TEST(PolygonGeometry, ValidateOnPeriodicAxes) {
  Domain d;
  d.lower = Vec3(0, 0, 0);
  d.upper = Vec3(1, 2, 3);
  const PolygonWall small({Vec3(0.2, 0.2, 1), Vec3(0.8, 0.2, 1), Vec3(0.5, 0.8, 1.5)});
  EXPECT_NO_THROW(small.validate("baffle", kGravityVector, d));
  d.periodic[1] = true;
  EXPECT_THROW(small.validate("baffle", kGravityVector, d), std::invalid_argument);
  // An inclined strip across y, from y = 0 to 2.
  const PolygonWall strip({Vec3(0.1, 0, 1), Vec3(0.6, 0, 2), Vec3(0.6, 2, 2), Vec3(0.1, 2, 1)});
  EXPECT_NO_THROW(strip.validate("side", kGravityVector, d));
  const PolygonWall skew({Vec3(0.1, 0, 1), Vec3(0.6, 0, 2), Vec3(0.7, 2, 2), Vec3(0.2, 2, 1)});
  EXPECT_THROW(skew.validate("side", kGravityVector, d), std::invalid_argument);
}

}  // namespace
}  // namespace carom
