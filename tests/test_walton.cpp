// Walton's e / mu / beta0 collision law (events/laws/walton.hpp): exact cases and exact identities.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "events/laws/walton.hpp"

namespace carom {
namespace {

struct Sphere {
  Vec3 position, velocity, spin;
  double mass, radius;
  bool wall = false;  // infinite mass and inertia
  double inertia() const { return 0.4 * mass * radius * radius; }
  double kinetic() const {
    return wall ? 0.0 : 0.5 * mass * velocity.squaredNorm() + 0.5 * inertia() * spin.squaredNorm();
  }
  ContactBody body() {
    return wall ? ContactBody{velocity, spin, 0.0, 0.0, 0.0}
                : ContactBody{velocity, spin, 1.0 / mass, radius, 1.0 / inertia()};
  }
};

Vec3 contact_velocity(const Sphere& s1, const Sphere& s2, const Vec3& n) {
  const double a2 = s2.wall ? 0.0 : s2.radius;
  return s1.velocity - s2.velocity - (s1.radius * s1.spin + a2 * s2.spin).cross(n);
}

// Reference: tests/VALIDATION.md, "Collision law: exact cases" (both rows, every column).
// Tolerance 1e-12: the values are exact decimals computed from the law with a handful of
// floating-point operations on O(1) numbers, so round-off is ~1e-15; any wrong factor
// (2/7, 1+e, the sliding beta) changes a column at the 1e-2 level.
struct ExactCase {
  double e, mu, beta0;
  bool sliding;
  Vec3 impulse, v1, v2;
  double w1z, w2z, energy_after;
};
/// How ctest lists a case (instead of its bytes).
void PrintTo(const ExactCase& c, std::ostream* out) {
  *out << "e = " << c.e << ", mu = " << c.mu << ", beta0 = " << c.beta0 << (c.sliding ? ", sliding" : ", sticking");
}

class WaltonExact : public ::testing::TestWithParam<ExactCase> {};

TEST_P(WaltonExact, MatchesTable) {
  const ExactCase& c = GetParam();
  Vec3 v1(1, 0.5, 0), v2(-1, 0, 0), w1(0, 0, 2), w2(0, 0, 0);
  const double m = 1.0, a = 0.5, inertia = 0.4 * m * a * a;
  const Vec3 n = (Vec3(0, 0, 0) - Vec3(1, 0, 0)).normalized();  // from 2 to 1
  auto energy = [&] {
    return 0.5 * m * (v1.squaredNorm() + v2.squaredNorm()) +
           0.5 * inertia * (w1.squaredNorm() + w2.squaredNorm());
  };
  EXPECT_NEAR(energy(), 1.325, 1e-12);
  ContactLaw law{c.e, c.mu, c.beta0};
  const CollisionOutcome out = collide(law, n, ContactBody{v1, w1, 1 / m, a, 1 / inertia},
                                       ContactBody{v2, w2, 1 / m, a, 1 / inertia});
  EXPECT_EQ(out.sliding, c.sliding);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(out.impulse[k], c.impulse[k], 1e-12) << "impulse component " << k;
    EXPECT_NEAR(v1[k], c.v1[k], 1e-12) << "v1' component " << k;
    EXPECT_NEAR(v2[k], c.v2[k], 1e-12) << "v2' component " << k;
  }
  EXPECT_NEAR(w1.z(), c.w1z, 1e-12);
  EXPECT_NEAR(w2.z(), c.w2z, 1e-12);
  EXPECT_NEAR(w1.x(), 0.0, 1e-12);
  EXPECT_NEAR(w1.y(), 0.0, 1e-12);
  EXPECT_NEAR(energy(), c.energy_after, 1e-12);
  EXPECT_NEAR(out.dissipated, 1.325 - c.energy_after, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(
    ValidationTable, WaltonExact,
    ::testing::Values(ExactCase{0.9, 0.3, 0.4, false, {-1.9, -0.3, 0}, {-0.9, 0.2, 0}, {0.9, 0.3, 0}, 0.5, -1.5, 1.0},
                      ExactCase{0.9, 0.1, 0.4, true, {-1.9, -0.19, 0}, {-0.9, 0.31, 0}, {0.9, 0.19, 0}, 1.05, -0.95, 0.97635}),
    // Named for ctest: the table's two rows differ in whether the contact slides.
    [](const ::testing::TestParamInfo<ExactCase>& info) {
      return std::string(info.param.sliding ? "sliding" : "sticking");
    });

Vec3 random_unit(Rng& rng) {
  for (;;) {
    const Vec3 v = rng.normal3();
    if (v.norm() > 1e-3) return v.normalized();
  }
}

// Exact identities of the law (tests/VALIDATION.md, "Collision law: identities") on 2e5 random
// collisions: sizes 0.05..2 m, masses 0.01..100 kg (so m12 ranges over 4 decades), e, mu in [0, 1],
// beta0 in [-1, 1], one collision in four against a wall (a ContactBody with zero inverse mass and
// inertia). Tolerance: every identity is exact algebra evaluated in double precision with O(10)
// operations, so errors are a few ulps of the largest term: 1e-12 relative to the natural scale of
// each quantity (momentum scale m|v|, energy scale KE) leaves 3 decades of margin and still fails
// on any wrong coefficient (errors would be O(1) relative).
TEST(WaltonIdentities, RandomCollisions) {
  Rng rng(2024);
  int sticking = 0, sliding = 0, walls = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    Sphere s1, s2;
    s1.mass = std::pow(10.0, rng.uniform(-2, 2));
    s1.radius = std::pow(10.0, rng.uniform(-1.3, 0.3));
    s2.wall = rng.uniform() < 0.25;
    s2.mass = s2.wall ? 1.0 : std::pow(10.0, rng.uniform(-2, 2));
    s2.radius = s2.wall ? 0.0 : std::pow(10.0, rng.uniform(-1.3, 0.3));
    const Vec3 n = random_unit(rng);
    const Vec3 c = rng.normal3();  // contact point
    s1.position = c + s1.radius * n;
    s2.position = c - s2.radius * n;
    s1.velocity = rng.normal3();
    s1.spin = rng.normal3() * std::pow(10.0, rng.uniform(-1, 1)) / s1.radius;
    s2.velocity = s2.wall ? Vec3(Vec3::Zero()) : rng.normal3();
    s2.spin = s2.wall ? Vec3(Vec3::Zero()) : Vec3(rng.normal3() / s2.radius);
    Vec3 g = contact_velocity(s1, s2, n);
    if (g.dot(n) >= 0.0) {  // make it approach: reverse body 1's normal velocity component
      s1.velocity -= 2.0 * (g.dot(n) + 0.1) * n;
      g = contact_velocity(s1, s2, n);
    }
    ASSERT_LT(g.dot(n), 0.0);
    const double gn = g.dot(n);
    const Vec3 gt = g - gn * n;
    ContactLaw law;
    law.restitution = rng.uniform();
    law.friction = rng.uniform();
    law.tangential_restitution = rng.uniform(-1, 1);
    const double m12 = s2.wall ? s1.mass : s1.mass * s2.mass / (s1.mass + s2.mass);

    const Sphere b1 = s1, b2 = s2;  // before
    const double energy_before = s1.kinetic() + s2.kinetic();
    const CollisionOutcome out = collide(law, n, s1.body(), s2.body());
    const double energy_after = s1.kinetic() + s2.kinetic();
    const double energy_scale = energy_before + 0.5 * m12 * g.squaredNorm();
    const double momentum_scale = b1.mass * b1.velocity.norm() + b2.mass * b2.velocity.norm() + m12 * g.norm();

    // Linear momentum: body 1 changes by J; body 2 by -J (a wall absorbs it).
    EXPECT_LT((b1.mass * (s1.velocity - b1.velocity) - out.impulse).norm(), 1e-12 * momentum_scale);
    if (!s2.wall) {
      const Vec3 before = b1.mass * b1.velocity + b2.mass * b2.velocity;
      const Vec3 after = s1.mass * s1.velocity + s2.mass * s2.velocity;
      EXPECT_LT((after - before).norm(), 1e-12 * momentum_scale) << "trial " << trial;
    }
    // Angular momentum of each particle about the contact point: I w + m (r - c) x v.
    auto angular = [&](const Sphere& s) -> Vec3 { return s.inertia() * s.spin + s.mass * (s.position - c).cross(s.velocity); };
    const double angular_scale1 = b1.inertia() * b1.spin.norm() + b1.radius * momentum_scale;
    EXPECT_LT((angular(s1) - angular(b1)).norm(), 1e-12 * angular_scale1) << "trial " << trial;
    if (!s2.wall) {
      const double angular_scale2 = b2.inertia() * b2.spin.norm() + b2.radius * momentum_scale;
      EXPECT_LT((angular(s2) - angular(b2)).norm(), 1e-12 * angular_scale2) << "trial " << trial;
    }
    // Energy never grows; `dissipated` is the kinetic energy difference.
    EXPECT_LE(energy_after, energy_before + 1e-12 * energy_scale) << "trial " << trial;
    EXPECT_NEAR(out.dissipated, energy_before - energy_after, 1e-12 * energy_scale) << "trial " << trial;
    // Normal restitution always holds: g_n' = -e g_n.
    const Vec3 g_after = contact_velocity(s1, s2, n);
    const double scale_g = g.norm();
    EXPECT_NEAR(g_after.dot(n), -law.restitution * gn, 1e-12 * scale_g) << "trial " << trial;
    const Vec3 gt_after = g_after - g_after.dot(n) * n;
    const double jn = out.impulse.dot(n), jt = (out.impulse - jn * n).norm();
    if (!out.sliding) {
      ++sticking;
      // Sticking: tangential contact velocity reversed by beta0, energy loss formula, and the
      // impulse inside the Coulomb cone.
      EXPECT_LT((gt_after + law.tangential_restitution * gt).norm(), 1e-12 * scale_g) << "trial " << trial;
      const double b0 = law.tangential_restitution, e = law.restitution;
      const double loss = 0.5 * m12 * ((1 - e * e) * gn * gn + (2.0 / 7.0) * (1 - b0 * b0) * gt.squaredNorm());
      EXPECT_NEAR(energy_before - energy_after, loss, 1e-12 * energy_scale) << "trial " << trial;
      EXPECT_LE(jt, law.friction * jn * (1 + 1e-12) + 1e-14 * momentum_scale) << "trial " << trial;
    } else {
      ++sliding;
      // Sliding: |J_t| = mu |J_n|, opposing g_t, and the slip does not reverse past -beta0 g_t.
      EXPECT_NEAR(jt, law.friction * jn, 1e-12 * momentum_scale) << "trial " << trial;
      if (jt > 0) {
        EXPECT_LT((out.impulse - jn * n).dot(gt), 0.0);
      }
      EXPECT_GE(gt_after.dot(gt), -law.tangential_restitution * gt.squaredNorm() - 1e-12 * gt.squaredNorm());
    }
    if (s2.wall) ++walls;
  }
  // The sample covers both regimes and walls in bulk.
  EXPECT_GT(sticking, 20000);
  EXPECT_GT(sliding, 20000);
  EXPECT_GT(walls, 20000);
}

// A separating or grazing contact gets no impulse (the law's stated behaviour).
TEST(WaltonIdentities, SeparatingContactIsLeftAlone) {
  Vec3 v1(1, 0.3, 0), v2(0, 0, 0), w1(0, 0, 1), w2(0, 0, 0);
  const Vec3 n(1, 0, 0);  // from 2 to 1; g.n = 1 > 0: separating
  const CollisionOutcome out = collide(ContactLaw{0.5, 0.5, 0.5}, n, ContactBody{v1, w1, 1, 0.5, 10},
                                       ContactBody{v2, w2, 1, 0.5, 10});
  EXPECT_EQ(out.impulse, Vec3::Zero());
  EXPECT_EQ(v1, Vec3(1, 0.3, 0));
  EXPECT_EQ(out.dissipated, 0.0);
}

// Static/kinetic Coulomb variant (ContactLaw.static_friction = mu_s > friction = mu_k, beta0 = 0).
// A sphere hits a wall head-on with tangential slip: the tangential impulse needed to stop the
// slip is (2/7) m |g_t|, the normal impulse (1+e) m |g_n|. With ratio
//   r = (2/7)|g_t| / ((1+e)|g_n|)
// it must stick (g_t' = 0) when r < mu_s and slide with |J_t| = mu_k |J_n| when r > mu_s.
// Tolerance 1e-12: exact algebra on O(1) numbers.
TEST(WaltonStaticKinetic, SticksBelowStaticLimitSlidesWithKineticAbove) {
  const double mu_s = 0.5, mu_k = 0.3, e = 0.8;
  ContactLaw law;
  law.restitution = e;
  law.friction = mu_k;
  law.static_friction = mu_s;
  law.tangential_restitution = 0.0;
  ASSERT_NO_THROW(law.validate("test"));
  const Vec3 n = Vec3::UnitZ();  // wall below, normal up towards the sphere
  for (double r : {0.05, 0.2, 0.35, 0.45, 0.49, 0.51, 0.6, 1.0, 3.0}) {
    const double gn = -1.0;                                  // approaching at 1 m/s
    const double gt = r * (1 + e) * std::abs(gn) * 3.5;     // slip speed giving ratio r
    const double m = 2.0, a = 0.3, inertia = 0.4 * m * a * a;
    Vec3 v(gt, 0, gn), w(0, 0, 0), wall_v(0, 0, 0), wall_w(0, 0, 0);
    const CollisionOutcome out =
        collide(law, n, ContactBody{v, w, 1 / m, a, 1 / inertia}, ContactBody{wall_v, wall_w, 0, 0, 0});
    const Vec3 g_after = v - (a * w).cross(n);
    const double jn = out.impulse.z(), jt = std::hypot(out.impulse.x(), out.impulse.y());
    EXPECT_NEAR(jn, m * (1 + e), 1e-12);
    if (r < mu_s) {
      EXPECT_FALSE(out.sliding) << "ratio " << r;
      EXPECT_NEAR(g_after.x(), 0.0, 1e-12) << "ratio " << r << ": a sticking contact stops slipping";
      EXPECT_NEAR(jt, (2.0 / 7.0) * m * gt, 1e-12);
      EXPECT_LE(jt, mu_s * jn + 1e-12);
    } else {
      EXPECT_TRUE(out.sliding) << "ratio " << r;
      EXPECT_NEAR(jt, mu_k * jn, 1e-12) << "ratio " << r << ": sliding uses the kinetic coefficient";
      EXPECT_GT(g_after.x(), 0.0) << "ratio " << r << ": still slipping forward";
    }
    EXPECT_NEAR(g_after.z(), e, 1e-12);
  }
}

}  // namespace
}  // namespace carom
