// The polygon wall's ballistic and relax contact times (core/walls/polygon.hpp) against a
// brute-force scan of the distance (its geometry: test_polygon_geometry.cpp).
//
// Reference distance: the closest point by another algorithm (Ericson's closest point on a
// triangle over a fan of triangles, tests/polygon_support.hpp), itself checked against a fine
// sampling of the polygon. Reference contact time: the gap G(s) = D(r(s)) - a, D the reference
// distance and r(s) the flight's exact closed form (rate 0: the ballistic parabola), scanned on
// 1e4 grid cells by tests/contact_oracle.hpp (sign changes, and dips found by the sign of
// G' = n.v, which is continuous: the distance to a convex set is once differentiable). Where a
// contact is predicted at s_p the scan ends at min(horizon, 1.01 s_p + 1e-3 horizon).
// Tolerance on times, as for the cone: 1e-9 of the case's time scale T (the horizon, or the
// time to cross the polygon if shorter) plus the conditioning of the root, 16 eps of the
// lengths involved over |G'| (G is known to round-off of the lengths). At the predicted time
// the sphere must not overlap by more than 1e-12 of (a + size) (the engine's bound is 1e-10 a)
// and must be approaching.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "contact_oracle.hpp"
#include "core/wall.hpp"
#include "polygon_support.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using polygon_test::log_uniform;
using polygon_test::oracle_closest;
using polygon_test::random_polygon;
using polygon_test::unit;
using test::Agreement;
using test::brute_force_contact;
using test::compare;
using test::GapFunction;
using test::Sample;

using carom::test::kEps;
using carom::test::kGravityVector;

// --- contact times against the scan ----------------------------------------------------------

struct PlateCase {
  PolygonWall plate;
  double a;        // sphere radius, m
  Vec3 r, v;       // state at s = 0
  RelaxFlight f;   // rate 0, drive g: a ballistic flight
  double horizon;  // s
};

GapFunction oracle_gap(const PlateCase& c) {
  return [&c](double s) {
    const Vec3 r = c.r + c.f.displacement(c.v, s), u = c.f.velocity(c.v, s);
    const Vec3 q = oracle_closest(c.plate.vertices(), r);
    const double d = (r - q).norm();
    return Sample{d - c.a, d > 0.0 ? (r - q).dot(u) / d : -u.norm()};
  };
}

RelaxFlight random_flight(Rng& rng, bool relax) {
  const Vec3 g = rng.uniform() < 0.5 ? kGravityVector : Vec3(9.81 * unit(rng));
  if (!relax) return {0.0, rng.uniform() < 0.25 ? Vec3::Zero() : g};
  if (rng.uniform() < 0.2) return {0.0, g};
  const double rate = log_uniform(rng, 1.0, 1e4);
  return {rate, g + rate * log_uniform(rng, 0.01, 10.0) * unit(rng)};
}

const char* kFamilies[] = {"anywhere", "face", "edge", "vertex", "graze", "slow"};

/// A point of the polygon and a unit direction e off it such that the point is the closest to
/// every point along e: family 1 the face (e = +-normal), 2 an edge's interior (e across the
/// edge, outward), 3 a vertex (e in its normal cone); 4 any of these.
std::pair<Vec3, Vec3> random_feature_point(Rng& rng, const PolygonWall& plate, int family) {
  const std::vector<Vec3>& p = plate.vertices();
  const std::size_t n = p.size();
  const Vec3& normal = plate.normal();
  if (family == 4) family = 1 + static_cast<int>(rng.uniform() * 3.0);
  const std::size_t k = static_cast<std::size_t>(rng.uniform() * n) % n;
  const Vec3 t = (p[(k + 1) % n] - p[k]).normalized();
  const Vec3 outward = t.cross(normal).normalized();
  if (family == 1) {
    // A point of the fan triangle (p0, pk, pk+1), kept off the edges.
    const std::size_t j = 1 + k % (n - 2);
    double b = rng.uniform(0.02, 0.96), c = rng.uniform(0.02, 0.96);
    if (b + c > 0.98) b = 0.98 - b, c = 0.98 - c;
    b = std::abs(b), c = std::abs(c);
    const Vec3 q = p[0] + b * (p[j] - p[0]) + c * (p[j + 1] - p[0]);
    return {q, rng.uniform() < 0.5 ? normal : Vec3(-normal)};
  }
  if (family == 2) {
    const double angle = rng.uniform(-1.5, 1.5);
    const Vec3 q = p[k] + rng.uniform(0.02, 0.98) * (p[(k + 1) % n] - p[k]);
    return {q, std::cos(angle) * outward + std::sin(angle) * normal};
  }
  const Vec3 back = (p[(k + n - 1) % n] - p[k]).normalized();  // towards the previous vertex
  for (;;) {
    const Vec3 e = unit(rng);
    if (e.dot(t) <= 0.0 && e.dot(back) <= 0.0) return {p[k], e};
  }
}

// Families: 0 anywhere within 2 sizes of the centre (half of them aimed at the plate; relax
// flights at speeds that cross that distance in 0.3..3 horizons); 1..3 aimed: the sphere touches
// the face, an edge or a vertex at a chosen time t while approaching (an earlier contact may come
// first); 4 graze: at t the sphere moves across e (G' = 0) at 1e-6..1e-3 of a off contact, inside
// or outside, with G'' > 0 (a minimum of G); 5 slow: within 1e-12..1e-3 of a of the plate at
// 1e-6..1e-2 m/s, or at rest.
PlateCase random_case(Rng& rng, int family, bool relax) {
  for (int attempt = 0;; ++attempt) {
    if (attempt > 100000) throw std::runtime_error("cannot build a plate case");
    const double size = log_uniform(rng, 0.005, 0.1);
    PlateCase c{PolygonWall(random_polygon(rng, size)),
                size * log_uniform(rng, 0.01, 0.5),
                Vec3::Zero(),
                Vec3::Zero(),
                random_flight(rng, relax),
                0.0};
    c.horizon = relax ? log_uniform(rng, 1e-5, 1e-2) : log_uniform(rng, 1e-3, 1.0);
    if (family == 0 || family == 5) {
      if (family == 0) {
        // Half of them aimed at a point within the plate's size of its centre.
        c.r = c.plate.centre() + 2.0 * size * std::cbrt(rng.uniform()) * unit(rng);
        c.v = log_uniform(rng, 0.01, 10.0) * unit(rng);
        const Vec3 aim = c.plate.centre() + size * rng.uniform() * unit(rng) - c.r;
        if (relax)  // speeds that cross the distance within 0.3..3 horizons
          c.v = aim.norm() / c.horizon * log_uniform(rng, 0.3, 3.0) * unit(rng);
        if (rng.uniform() < 0.5) c.v = c.v.norm() * aim.normalized();
      } else {
        const auto [q, e] = random_feature_point(rng, c.plate, 4);
        c.r = q + c.a * (1.0 + log_uniform(rng, 1e-12, 1e-3)) * e;
        c.v = rng.uniform() < 0.25 ? Vec3(Vec3::Zero())
                                   : Vec3(log_uniform(rng, 1e-6, 1e-2) * unit(rng));
      }
    } else {
      const double t = rng.uniform(0.02, 1.2) * c.horizon;
      c.v = (family == 4 ? log_uniform(rng, 0.01, 1.0) : log_uniform(rng, 0.01, 10.0)) * unit(rng);
      const Vec3 u = c.f.velocity(c.v, t);
      const auto [q, e] = random_feature_point(rng, c.plate, family);
      Vec3 r_t = q + c.a * e;
      if (family != 4) {
        if (!(u.dot(e) < 0.0)) continue;  // not approaching there
      } else {
        // Make u tangential (G' = 0): u(t) = alpha v + drive t phi1 with alpha = e^{-rate t}
        // (relax_flight.hpp), so removing (u.e / alpha) e from v removes u's part along e.
        const double alpha = std::exp(-c.f.rate * t);
        if (!(alpha > 0.01))
          continue;  // the change to v would be huge: a flight that
                     // cancels to round-off
        c.v -= (u.dot(e) / alpha) * e;
        const Vec3 w = c.f.velocity(c.v, t);
        // G'' = |u|^2 / D about an edge or a vertex (u is across e; 0 over the face) + e.a_c:
        // > 0 for a minimum.
        const bool face = std::abs(std::abs(e.dot(c.plate.normal())) - 1.0) < 1e-12;
        const double curvature = (face ? 0.0 : w.squaredNorm() / c.a) + e.dot(c.f.acceleration(w));
        if (!(curvature > 0.0)) continue;
        r_t += (rng.uniform() < 0.5 ? -1.0 : 1.0) * c.a * log_uniform(rng, 1e-6, 1e-3) * e;
      }
      c.r = r_t - c.f.displacement(c.v, t);
    }
    if (!(oracle_gap(c)(0.0).value > 0.0)) continue;  // starts in contact
    return c;
  }
}

double predicted_time(const PlateCase& c, bool relax) {
  if (relax) return c.plate.relax_contact_time(c.r, c.v, c.a, c.f, c.horizon);
  const double s = c.plate.ballistic_contact_time(c.r, c.v, c.a, c.f.drive);
  return s <= c.horizon ? s : kNever;
}

void check_case(Agreement& stats, const PlateCase& c, double predicted, const char* family,
                int trial) {
  const GapFunction G = oracle_gap(c);
  const double end =
      predicted == kNever ? c.horizon : std::min(c.horizon, predicted * 1.01 + 1e-3 * c.horizon);
  const double brute = brute_force_contact(G, end, 10000);
  const double speed = std::max(c.v.norm(), c.f.velocity(c.v, c.horizon).norm());
  const double length =
      c.plate.size() + c.a + c.r.norm() + c.plate.centre().norm() + speed * c.horizon;
  const double scale = speed > 0.0 ? std::min(c.horizon, c.plate.size() / speed) : c.horizon;
  const double slope = brute == kNever ? 1.0 : std::max(std::abs(G(brute).slope), 1e-300);
  compare(stats, G, predicted, brute, 1e-9 * scale + 16.0 * kEps * length / slope,
          c.plate.size() + c.a, family, trial);
}

// 3000 random ballistic flights (six families, 500 each; a quarter without gravity, half of
// the rest with gravity in a random direction) against the scan.
TEST(PolygonBallistic, AgreesWithBruteForceScan) {
  Rng rng(72);
  Agreement stats[6];
  for (int trial = 0; trial < 3000; ++trial) {
    const int family = trial % 6;
    const PlateCase c = random_case(rng, family, false);
    const double predicted = predicted_time(c, false);
    check_case(stats[family], c, predicted, kFamilies[family], trial);
  }
  for (int f = 0; f < 6; ++f) {
    std::printf(
        "[ polygon ] ballistic %-8s: %d cases, %d contacts, worst error %.2g of "
        "tolerance\n",
        kFamilies[f], stats[f].cases, stats[f].hits, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 20) << kFamilies[f];
  }
  EXPECT_GT(stats[4].misses, 50) << "grazes that miss";
}

// 3000 random relax flights (six families) against the scan, with the search's cost.
TEST(PolygonRelax, AgreesWithBruteForceScan) {
  Rng rng(73);
  Agreement stats[6];
  long iterations = 0;
  int most = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int family = trial % 6;
    const PlateCase c = random_case(rng, family, true);
    const RelaxContactSearch search = c.plate.relax_contact_search(c.r, c.v, c.a, c.f, c.horizon);
    iterations += search.iterations;
    most = std::max(most, search.iterations);
    check_case(stats[family], c, search.time, kFamilies[family], trial);
  }
  for (int f = 0; f < 6; ++f) {
    std::printf("[ polygon ] relax %-8s: %d cases, %d contacts, worst error %.2g of tolerance\n",
                kFamilies[f], stats[f].cases, stats[f].hits, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 20) << kFamilies[f];
  }
  EXPECT_GT(stats[4].misses, 50) << "grazes that miss";
  std::printf("[ polygon ] relax search iterations: mean %.2f, max %d\n", double(iterations) / 3000,
              most);
}

// Rate 0: the relax search (conservative advancement on the distance) and the ballistic
// quartics (per feature) are two independent algorithms for the same flight; they agree on
// every contact and miss, to the scan comparison's tolerance (both are round-off accurate).
TEST(PolygonRelax, BallisticLimitMatchesTheQuartics) {
  Rng rng(76);
  int contacts = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const PlateCase c = random_case(rng, trial % 6, false);
    const double ballistic = predicted_time(c, false);
    const double relax = c.plate.relax_contact_time(c.r, c.v, c.a, c.f, c.horizon);
    SCOPED_TRACE(::testing::Message() << kFamilies[trial % 6] << " case " << trial);
    if (ballistic == kNever) {
      EXPECT_EQ(relax, kNever);
      continue;
    }
    ++contacts;
    ASSERT_NE(relax, kNever);
    const double speed = std::max(c.v.norm(), c.f.velocity(c.v, c.horizon).norm());
    const double length =
        c.plate.size() + c.a + c.r.norm() + c.plate.centre().norm() + speed * c.horizon;
    const double scale = speed > 0.0 ? std::min(c.horizon, c.plate.size() / speed) : c.horizon;
    const double slope = std::max(std::abs(oracle_gap(c)(ballistic).slope), 1e-300);
    EXPECT_NEAR(relax, ballistic, 1e-9 * scale + 16.0 * kEps * length / slope);
  }
  EXPECT_GT(contacts, 1000);
}

// Over the face's interior the polygon is the plane: the same contact time as a PlaneWall
// through it (to 1e-12 relative: the same quadratic, solved as a quartic's factor and polished).
TEST(PolygonBallistic, OverTheFaceItIsThePlane) {
  const PolygonWall plate({Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)});
  const PlaneWall plane{Vec3::Zero(), Vec3::UnitZ()};
  Rng rng(74);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 r(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(0.02, 0.2));
    const Vec3 v(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), rng.uniform(-1.0, 1.0));
    const double expected = plane.ballistic_contact_time(r, v, 0.01, kGravityVector);
    EXPECT_NEAR(plate.ballistic_contact_time(r, v, 0.01, kGravityVector), expected, 1e-12 * expected);
  }
}

// After a bounce (at contact, moving away: by round-off a hair inside or outside) the next
// contact is the true next one, never "now": a sphere bounced off the face, an edge and a
// vertex under gravity comes back at the time the scan finds (to 1e-9 of the flight).
TEST(PolygonBallistic, AfterABounceTheNextContactIsTheNextOne) {
  const PolygonWall plate(
      {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.1, 0.1, 0.02), Vec3(0, 0.1, 0.02)});
  const double a = 0.005;
  Rng rng(75);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto [q, e] = random_feature_point(rng, plate, 1 + trial % 3);
    for (double hair : {-1e-15, 0.0, 1e-15}) {
      PlateCase c{plate, a, q + (a + hair) * e, Vec3::Zero(), RelaxFlight{0.0, kGravityVector}, 1.0};
      c.v = rng.uniform(0.05, 1.0) * e + rng.uniform(0.0, 0.3) * unit(rng);
      if (!(c.v.dot(e) > 0.05)) continue;
      const double predicted = plate.ballistic_contact_time(c.r, c.v, a, kGravityVector);
      EXPECT_GT(predicted, 1e-6) << "trial " << trial;
      // The scan from just after the bounce (the state at 1e-7 s, clear of the plate).
      const GapFunction G = oracle_gap(c);
      if (!(G(1e-7).value > 0.0)) continue;
      PlateCase later = c;
      later.r = c.r + c.f.displacement(c.v, 1e-7);
      later.v = c.f.velocity(c.v, 1e-7);
      const double brute = brute_force_contact(oracle_gap(later), 1.0, 20000);
      if (brute == kNever) {
        EXPECT_TRUE(predicted == kNever || predicted > 1.0) << "trial " << trial;
      } else {
        EXPECT_NEAR(predicted, brute + 1e-7, 1e-9) << "trial " << trial;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace carom
