// The cone wall (core/walls/cone.hpp): geometry, and its ballistic and relax contact times
// against a brute-force scan of the locus gap.
//
// Reference: the locus gap G(s) = L(z(s)) - rho(s) (L: the radius of the locus of touching
// centres, rho: the centre's distance from the axis), with the trajectory from the flight's
// exact closed form (a ballistic flight is the relax flight with rate 0, exactly:
// RelaxPhi.ZeroRateIsTheBallisticParabolaExactly), scanned on 1e4 grid cells by
// tests/contact_oracle.hpp (sign changes and dips; far finer than the few extrema of G per
// horizon). Where a contact is predicted at s_p the scan ends at min(horizon, 1.01 s_p + 1e-3
// horizon). Tolerance on times: 1e-9 of the case's time scale T (the horizon, or the time to
// cross the locus radius if shorter) plus the conditioning of the root: G is known to
// round-off of the lengths involved (16 eps of them), which moves a root by that / |G'|.
// At the predicted time the sphere must not overlap by more than 1e-12 of (a + L) (the
// engine's bound is 1e-10 a) and must be approaching.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "contact_oracle.hpp"
#include "core/relax_roots.hpp"
#include "core/rng.hpp"
#include "core/wall.hpp"
#include "tests/random_draws.hpp"

namespace carom {
namespace {

using test::Agreement;
using test::brute_force_contact;
using test::compare;
using test::GapFunction;
using test::Sample;
using test::kEps;
using test::kGravityVector;
using test::log_uniform;
using test::random_flight;
using test::unit;

constexpr double kTwoPi = 6.283185307179586;
Vec3 horizontal(double angle) {
  return Vec3(std::cos(angle), std::sin(angle), 0.0);
}

// --- geometry --------------------------------------------------------------------------------

// The gap against the distance from the centre to the generator line in its meridian plane
// (a cross product, another formula), the normal against the line's direction (perpendicular,
// unit, pointing inwards), and the locus: gap 0 exactly where rho = R(z) - a / cos(alpha).
// Tolerance 1e-14 of the lengths (a few roundings of numbers up to 3 m).
TEST(ConeGeometry, GapNormalAndLocus) {
  Rng rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const double zb = rng.uniform(-1.0, 0.0), zt = zb + log_uniform(rng, 0.1, 2.0);
    const double rb = log_uniform(rng, 0.01, 1.0), rt = log_uniform(rng, 0.01, 1.0);
    const ConeWall cone(rng.uniform(-1, 1), rng.uniform(-1, 1), zb, rb, zt, rt);
    const double z = rng.uniform(zb, zt), a = 0.1 * std::min(rb, rt);
    const Vec3 e = horizontal(rng.uniform(0.0, kTwoPi));
    const double rho = cone.radius_at(z) * rng.uniform(0.0, 1.5);
    const Vec3 r = Vec3(cone.axis_x(), cone.axis_y(), z) + rho * e;
    // Meridian plane: points (rho, z); the generator through (rb, zb) and (rt, zt).
    const Eigen::Vector2d p(rho, z), b(rb, zb), t(rt, zt);
    const Eigen::Vector2d along = (t - b).normalized();
    const double cross = along.x() * (p - b).y() - along.y() * (p - b).x();  // > 0: inside
    EXPECT_NEAR(cone.gap(r, a), cross - a, 1e-14 * (1.0 + rho + std::abs(z)));
    const Vec3 n = cone.contact_normal(r);
    const Vec3 tangent = along.x() * e + along.y() * Vec3::UnitZ();
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    EXPECT_NEAR(n.dot(tangent), 0.0, 1e-15);
    EXPECT_LT(n.dot(e), 0.0) << "the normal points inwards";
    const Vec3 on_locus = Vec3(cone.axis_x(), cone.axis_y(), z) + cone.locus_at(z, a) * e;
    EXPECT_NEAR(cone.gap(on_locus, a), 0.0, 1e-15 * (1.0 + rb + rt));
  }
  EXPECT_THROW(ConeWall(0, 0, 1.0, 0.1, 1.0, 0.2), std::invalid_argument);  // z_top = z_bottom
  EXPECT_THROW(ConeWall(0, 0, 0.0, -0.1, 1.0, 0.2), std::invalid_argument);
  EXPECT_THROW(ConeWall(0, 0, 0.0, 0.0, 1.0, 0.0), std::invalid_argument);
}

// The cone's checks: gravity along z, z walled, apex outside the domain's heights.
TEST(ConeGeometry, Validate) {
  Domain d;
  d.lower = Vec3(-1, -1, 0);
  d.upper = Vec3(1, 1, 2);
  const std::vector<Wall> hopper{Wall::cone("hopper", 0, 0, 0.5, 0.2, 1.5, 0.8)};  // apex z = 0.17
  EXPECT_THROW(validate_walls(hopper, kGravityVector, d), std::invalid_argument);
  const std::vector<Wall> fine{Wall::cone("hopper", 0, 0, 0.5, 0.6, 1.5, 0.8)};  // apex z = -2.5
  EXPECT_NO_THROW(validate_walls(fine, kGravityVector, d));
  EXPECT_THROW(validate_walls(fine, Vec3(0.1, 0, -9.81), d), std::invalid_argument);
  d.periodic[2] = true;
  EXPECT_THROW(validate_walls(fine, kGravityVector, d), std::invalid_argument);
  // The cylinder's check, unchanged.
  try {
    validate_walls({Wall::cylinder("pipe", 0, 0, 1)}, Vec3(1, 0, 0), d);
    FAIL() << "tilted gravity accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "wall 'pipe': a cylinder's axis is along z, so gravity must be along z too");
  }
}

// --- random cases ----------------------------------------------------------------------------

struct ConeCase {
  ConeWall cone;
  double a;        // sphere radius, m
  Vec3 r, v;       // state at s = 0
  RelaxFlight f;   // rate 0, drive g: a ballistic flight
  double horizon;  // s
};

GapFunction locus_gap(const ConeCase& c) {
  return [=](double s) {
    const Vec3 r = c.r + c.f.displacement(c.v, s), u = c.f.velocity(c.v, s);
    const double x = r.x() - c.cone.axis_x(), y = r.y() - c.cone.axis_y();
    const double rho = std::hypot(x, y);
    const double radial = rho > 0.0 ? (x * u.x() + y * u.y()) / rho : std::hypot(u.x(), u.y());
    return Sample{c.cone.locus_at(r.z(), c.a) - rho, c.cone.slope() * u.z() - radial};
  };
}

/// A ballistic flight (under gravity, or none at all a quarter of the time) or a relax flight
/// (random_flight, a fifth of them under gravity alone).
RelaxFlight cone_flight(Rng& rng, bool relax) {
  if (!relax) return {0.0, rng.uniform() < 0.25 ? Vec3::Zero() : kGravityVector};
  return random_flight(rng, 0.2);
}

// A cone about the axis through (ax, ay) with locus radius ~ r_mid at z = 0, half-angle
// 3..72 degrees, widening upwards (hopper) or downwards (duct); the defining circles at
// z = +-h keep both radii positive.
ConeWall random_cone(Rng& rng, bool hopper, double r_mid) {
  const double k = (hopper ? 1.0 : -1.0) * log_uniform(rng, 0.05, 3.0);
  const double h = 0.9 * r_mid / std::abs(k);
  return ConeWall(rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), -h, r_mid - k * h, h,
                  r_mid + k * h);
}

const char* kFamilies[] = {"anywhere", "aimed", "graze", "slow", "throat"};

// Families: 0 anywhere inside; 1 aimed: in contact and moving out at a chosen time t (an
// earlier contact may come first); 2 graze: the locus gap has a minimum of +-1e-6..1e-3 of L
// at t (in a duct under gravity, or pushed by the gas); 3 slow: within 1e-12..1e-3 of L of the
// wall at 1e-6..1e-2 m/s, or at rest; 4 throat: where the locus is 1e-4..1 sphere radii wide,
// near the axis (down to 1e-9 of L from it): the apex of the locus is close.
ConeCase random_case(Rng& rng, int family, bool relax) {
  for (int attempt = 0;; ++attempt) {
    if (attempt > 10000) throw std::runtime_error("cannot build a cone case");
    const double r_mid = log_uniform(rng, 0.005, 0.05);
    const bool hopper = family == 2 && !relax ? false : rng.uniform() < 0.6;
    ConeCase c{random_cone(rng, hopper, r_mid),
               r_mid * log_uniform(rng, 0.01, 0.3),
               Vec3::Zero(),
               Vec3::Zero(),
               RelaxFlight{},
               0.0};
    c.f = cone_flight(rng, relax);
    c.horizon = relax ? log_uniform(rng, 1e-5, 1e-2) : log_uniform(rng, 1e-3, 1.0);
    const ConeWall& cone = c.cone;
    const Vec3 axis(cone.axis_x(), cone.axis_y(), 0.0);
    const double k = cone.slope();
    const double z_lo = cone.z_bottom(), z_hi = cone.z_top();
    const Vec3 e = horizontal(rng.uniform(0.0, kTwoPi));
    if (family == 0 || family == 3 || family == 4) {
      double z = rng.uniform(z_lo, z_hi);
      if (family == 4) {
        const double L = c.a * log_uniform(rng, 1e-4, 1.0);
        z = cone.z_bottom() + (L + c.a * cone.secant() - cone.radius_bottom()) / k;
      }
      const double L = cone.locus_at(z, c.a);
      if (!(L > 0.0)) continue;
      double rho = L * std::sqrt(rng.uniform());
      if (family == 3) rho = L * (1.0 - log_uniform(rng, 1e-12, 1e-3));
      if (family == 4)
        rho = rng.uniform() < 0.5 ? L * rng.uniform() : L * log_uniform(rng, 1e-9, 1e-3);
      c.r = axis + rho * e + Vec3(0, 0, z);
      c.v = log_uniform(rng, 0.01, 10.0) * unit(rng);
      if (family == 3)
        c.v = rng.uniform() < 0.25 ? Vec3(Vec3::Zero())
                                   : Vec3(log_uniform(rng, 1e-6, 1e-2) * unit(rng));
      if (family == 4)
        c.v = log_uniform(rng, 1e-3, 1.0) * (Vec3(0, 0, k > 0.0 ? -1.0 : 1.0) + 0.3 * unit(rng));
    } else {
      // The state at t: velocity from a chosen start velocity, the position placed on (aimed)
      // or next to (graze) the locus; then the start position is what the flight displaces.
      const double t = rng.uniform(0.02, 1.2) * c.horizon;
      c.v = (family == 2 ? log_uniform(rng, 0.01, 1.0) : log_uniform(rng, 0.01, 10.0)) * unit(rng);
      const Vec3 u = c.f.velocity(c.v, t), acceleration = c.f.acceleration(u);
      const double z = rng.uniform(z_lo, z_hi);
      const double L = cone.locus_at(z, c.a);
      if (!(L > 0.0)) continue;
      const Eigen::Vector2d u_h = u.head<2>();
      double rho = L;
      Vec3 radial = e;
      if (family == 1) {
        if (k * u.z() - u_h.dot(e.head<2>()) >= 0.0) {  // not moving out: aim along u_h
          if (!(u_h.norm() > k * u.z())) continue;
          radial = Vec3(u_h.x(), u_h.y(), 0.0).normalized();
        }
      } else {
        // G' = k u_z - u_h.e_rho = 0 at t; G'' = k a_z - (|u_h|^2 - (k u_z)^2) / rho - e_rho.a_h
        // > 0: a minimum of G, of depth delta.
        const double along = k * u.z();
        if (!(u_h.norm() > std::abs(along))) continue;
        const double base = std::atan2(u_h.y(), u_h.x());
        const double turn = std::acos(along / u_h.norm()) * (rng.uniform() < 0.5 ? 1.0 : -1.0);
        radial = horizontal(base + turn);
        const double delta = (rng.uniform() < 0.5 ? -1.0 : 1.0) * L * log_uniform(rng, 1e-6, 1e-3);
        rho = L - delta;
        const double curvature = k * acceleration.z() - (u_h.squaredNorm() - along * along) / rho -
                                 radial.head<2>().dot(acceleration.head<2>());
        if (!(curvature > 0.0)) continue;
      }
      const Vec3 r_t = axis + rho * radial + Vec3(0, 0, z);
      c.r = r_t - c.f.displacement(c.v, t);
    }
    if (!(locus_gap(c)(0.0).value > 0.0)) continue;  // starts inside
    return c;
  }
}

double predicted_time(const ConeCase& c, bool relax) {
  if (relax) return c.cone.relax_contact_time(c.r, c.v, c.a, c.f, c.horizon);
  const double s = c.cone.ballistic_contact_time(c.r, c.v, c.a, c.f.drive);
  return s <= c.horizon ? s : kNever;
}

void check_case(Agreement& stats, const ConeCase& c, double predicted, const char* family,
                int trial) {
  const GapFunction G = locus_gap(c);
  const double end =
      predicted == kNever ? c.horizon : std::min(c.horizon, predicted * 1.01 + 1e-3 * c.horizon);
  const double brute = brute_force_contact(G, end, 10000);
  const double L0 = c.cone.locus_at(c.r.z(), c.a);
  const double speed = std::max(c.v.norm(), c.f.velocity(c.v, c.horizon).norm());
  const double k = std::abs(c.cone.slope());
  const double length = L0 + c.a + (1.0 + k) * (c.r.norm() + speed * c.horizon);
  const double scale = speed > 0.0 ? std::min(c.horizon, L0 / speed) : c.horizon;
  const double slope = brute == kNever ? 1.0 : std::max(std::abs(G(brute).slope), 1e-300);
  compare(stats, G, predicted, brute, 1e-9 * scale + 16.0 * kEps * length / slope, L0 + c.a, family,
          trial);
}

// 2500 random ballistic flights (five families, 500 each; one in four without gravity in the
// non-graze families) against the scan.
TEST(ConeBallistic, AgreesWithBruteForceScan) {
  Rng rng(51);
  Agreement stats[5];
  double seconds = 0.0;
  int calls = 0;
  for (int trial = 0; trial < 2500; ++trial) {
    const int family = trial % 5;
    const ConeCase c = random_case(rng, family, false);
    const auto start = std::chrono::steady_clock::now();
    const double predicted = predicted_time(c, false);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++calls;
    check_case(stats[family], c, predicted, kFamilies[family], trial);
  }
  for (int f = 0; f < 5; ++f) {
    std::printf("[ cone ] ballistic %-8s: %d cases, %d contacts, worst error %.2g of tolerance\n",
                kFamilies[f], stats[f].cases, stats[f].hits, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 20) << kFamilies[f];
  }
  EXPECT_GT(stats[2].misses, 50) << "grazes that miss";
  std::printf("[ cone ] ballistic prediction: %.0f ns per call\n", 1e9 * seconds / calls);
}

// 2500 random relax flights (five families) against the scan, with the search's cost.
TEST(ConeRelax, AgreesWithBruteForceScan) {
  Rng rng(52);
  Agreement stats[5];
  long iterations = 0;
  int most = 0;
  for (int trial = 0; trial < 2500; ++trial) {
    const int family = trial % 5;
    const ConeCase c = random_case(rng, family, true);
    const RelaxContactSearch search = c.cone.relax_contact_search(c.r, c.v, c.a, c.f, c.horizon);
    iterations += search.iterations;
    most = std::max(most, search.iterations);
    check_case(stats[family], c, search.time, kFamilies[family], trial);
  }
  for (int f = 0; f < 5; ++f) {
    std::printf("[ cone ] relax %-8s: %d cases, %d contacts, worst error %.2g of tolerance\n",
                kFamilies[f], stats[f].cases, stats[f].hits, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 20) << kFamilies[f];
  }
  EXPECT_GT(stats[2].misses, 50) << "grazes that miss";
  std::printf("[ cone ] relax search iterations: mean %.2f, max %d\n", double(iterations) / 2500,
              most);
}

// Rate 0: the relax search and the ballistic quartic agree (both round-off accurate: the
// conditioning tolerance of the scan comparison, with 1e-12 of the time scale).
TEST(ConeRelax, BallisticLimitMatchesTheQuartic) {
  Rng rng(53);
  int contacts = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    ConeCase c = random_case(rng, trial % 5, false);
    c.f = RelaxFlight{0.0, trial % 4 ? kGravityVector : Vec3::Zero()};
    const double quartic = predicted_time(c, false);
    const double relax = predicted_time(c, true);
    if (quartic == kNever) {
      EXPECT_EQ(relax, kNever) << trial;
      continue;
    }
    ++contacts;
    ASSERT_NE(relax, kNever) << trial;
    const GapFunction G = locus_gap(c);
    const double speed = std::max(c.v.norm(), c.f.velocity(c.v, c.horizon).norm());
    const double L0 = c.cone.locus_at(c.r.z(), c.a);
    const double length =
        L0 + c.a + (1.0 + std::abs(c.cone.slope())) * (c.r.norm() + speed * c.horizon);
    const double slope = std::max(std::abs(G(quartic).slope), 1e-300);
    EXPECT_NEAR(relax, quartic,
                1e-12 * std::min(c.horizon, L0 / speed) + 32.0 * kEps * length / slope)
        << trial;
  }
  EXPECT_GT(contacts, 300);
}

// Slope 0: the cone is the cylinder of radius R; its contact times are the cylinder's (the
// quadratic F is the cylinder's |d + u s|^2 - (R - a)^2, solved another way; the relax search
// is the cylinder's term for term but for the tolerance's round-off part): 1e-12 of the time
// scale plus the conditioning.
TEST(ConeRelax, CylinderLimitMatchesTheCylinder) {
  Rng rng(54);
  int contacts = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const bool relax = trial % 2;
    ConeCase c = random_case(rng, trial % 5 == 4 ? 0 : trial % 5, relax);
    const double R = c.cone.radius_at(c.r.z());
    c.cone = ConeWall(c.cone.axis_x(), c.cone.axis_y(), -1.0, R, 1.0, R);
    if (!(c.cone.gap(c.r, c.a) > 0.0)) continue;
    const CylinderWall cylinder{Vec3(c.cone.axis_x(), c.cone.axis_y(), 0.0), R};
    const double as_cone = predicted_time(c, relax);
    double as_cylinder = relax ? cylinder.relax_contact_time(c.r, c.v, c.a, c.f, c.horizon)
                               : cylinder.ballistic_contact_time(c.r, c.v, c.a, c.f.drive);
    if (!(as_cylinder <= c.horizon)) as_cylinder = kNever;
    if (as_cylinder == kNever) {
      EXPECT_EQ(as_cone, kNever) << trial;
      continue;
    }
    ++contacts;
    ASSERT_NE(as_cone, kNever) << trial;
    const GapFunction G = locus_gap(c);
    const double speed = std::max(c.v.norm(), c.f.velocity(c.v, c.horizon).norm());
    const double slope = std::max(std::abs(G(as_cylinder).slope), 1e-300);
    EXPECT_NEAR(as_cone, as_cylinder,
                1e-12 * std::min(c.horizon, R / speed) +
                    32.0 * kEps * (R + c.r.norm() + speed * c.horizon) / slope)
        << trial;
  }
  EXPECT_GT(contacts, 200);
}

// --- touching rules ----------------------------------------------------------------------------

// A hopper (R = 0.02 m at z = 0 to 0.04 m at z = 0.02: slope 1, 45 degrees), a sphere of
// radius 1 mm on the locus (G = 0 to round-off). Moving out returns 0 (a few ulps); moving in
// under gravity it comes back: at the time the scan finds; at rest in a duct without gravity:
// never; falling down the axis of the hopper, it lands where the locus closes (q = 0: the
// sphere touches the whole circle at once), at sqrt(2 h / g) with h the height above there.
TEST(ConeContact, TouchingRules) {
  const ConeWall hopper(0.0, 0.0, 0.0, 0.02, 0.02, 0.04);
  const double a = 1e-3, z = 0.01;
  const Vec3 e(1, 0, 0);
  const Vec3 on = hopper.locus_at(z, a) * e + Vec3(0, 0, z);
  const Vec3 out = 0.1 * (e - Vec3(0, 0, 1)).normalized();  // along -n, outward
  EXPECT_LE(hopper.ballistic_contact_time(on, out, a, kGravityVector), 1e-15);
  const RelaxFlight ballistic{0.0, kGravityVector};
  EXPECT_LE(hopper.relax_contact_time(on, out, a, ballistic, 1e-2), 1e-15);
  // Moving in at 0.1 m/s: gravity brings it back (normal acceleration g cos(alpha)).
  const ConeCase back{hopper, a, on, -out, ballistic, 0.1};
  for (bool relax : {false, true}) {
    const double predicted = predicted_time(back, relax);
    const double brute = brute_force_contact(locus_gap(back), 0.1, 100000);
    ASSERT_NE(brute, kNever);
    EXPECT_GT(predicted, 1e-3);
    EXPECT_NEAR(predicted, brute, 1e-9 * 0.1) << (relax ? "relax" : "ballistic");
  }
  // At rest without gravity: never.
  const Vec3 inside = 0.5 * hopper.locus_at(z, a) * e + Vec3(0, 0, z);
  EXPECT_EQ(hopper.ballistic_contact_time(inside, Vec3::Zero(), a, Vec3::Zero()), kNever);
  EXPECT_EQ(hopper.relax_contact_time(inside, Vec3::Zero(), a, RelaxFlight{}, 1e-2), kNever);
  // Down the axis: the locus closes at z0 = z_bottom + (a sec - R_bottom) / slope.
  const double closes = (a * hopper.secant() - 0.02) / 1.0;
  const double height = 0.01 - closes;
  for (double offset : {0.0, 1e-12, 1e-9}) {
    const Vec3 r(offset, 0.0, 0.01);
    const double expected = std::sqrt(2.0 * height / 9.81);
    const double tolerance = 1e-12 + 2.0 * offset / std::sqrt(2.0 * 9.81 * height);
    EXPECT_NEAR(hopper.ballistic_contact_time(r, Vec3::Zero(), a, kGravityVector), expected, tolerance)
        << "offset " << offset;
    EXPECT_NEAR(hopper.relax_contact_time(r, Vec3::Zero(), a, ballistic, 1.0), expected,
                tolerance + 1e-9)
        << "offset " << offset;
  }
}

}  // namespace
}  // namespace carom
