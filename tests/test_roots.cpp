// core/roots.hpp against brute-force searches that cannot miss a crossing.
//
// first_upward_crossing(A, B, C): the earliest s >= 0 where q(s) = A s^2 + B s + C crosses
// zero upward. This is the wall and cell-crossing prediction under gravity (gravity does not
// cancel against a fixed plane or cell face). Oracle: q sampled on 2e4 points of [0, S], where
// S bounds every root, with bisection of the first bracket.
//
// sphere_contact_time(dr, dv, contact): the pair prediction (gravity cancels between two
// particles, so the relative motion is linear). Oracle: conservative advancement, which steps
// by (distance - contact + tol)/|dv| and so can never step over a contact, because the
// distance cannot shrink faster than |dv|.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "core/roots.hpp"

namespace carom {
namespace {

double q_of(double A, double B, double C, double s) { return (A * s + B) * s + C; }

struct Quadratic {
  double A, B, C;
};

// Checks one quadratic. Tolerance on q: 1e-12 of the size of its terms at s (round-off of the
// closed form is a few ulps of the largest term); on s where the root is well conditioned
// (|q'| S not tiny against the terms): 1e-9 S.
void check_quadratic(const Quadratic& c, const char* family, int trial) {
  const double A = c.A, B = c.B, C = c.C;
  const double s_engine = first_upward_crossing(A, B, C);
  auto scale = [&](double s) { return std::abs(A) * s * s + std::abs(B) * s + std::abs(C); };
  SCOPED_TRACE(::testing::Message() << family << " trial " << trial << ": A=" << A << " B=" << B << " C=" << C
                                    << " engine s=" << s_engine);
  ASSERT_FALSE(std::isnan(s_engine));
  ASSERT_GE(s_engine, 0.0);
  // Every root lies in [0, S].
  const double S = (A != 0.0) ? 1.0 + (std::abs(B) + std::abs(C)) / std::abs(A)
                              : (B != 0.0 ? 1.0 + 2.0 * std::abs(C / B) : 1.0);
  if (C > 0.0) {
    // Already across (round-off overlap): 0 when moving outward, else the later upward root.
    if (B > 0.0) {
      EXPECT_EQ(s_engine, 0.0);
      return;
    }
  }
  // Brute force: first sample that is clearly outside after starting inside.
  const int samples = 20000;
  double s_prev = 0.0, s_bf = kNever, s_bracket_hi = kNever;
  bool inside_seen = C <= 0.0;
  for (int k = 1; k <= samples; ++k) {
    const double s = S * k / samples;
    const double q = q_of(A, B, C, s);
    if (q <= 0.0) inside_seen = true;
    if (inside_seen && q > 1e-12 * scale(s) && q_of(A, B, C, s_prev) <= 0.0) {
      double lo = s_prev, hi = s;
      for (int it = 0; it < 200 && lo < hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (q_of(A, B, C, mid) <= 0.0 ? lo : hi) = mid;
      }
      s_bf = 0.5 * (lo + hi);
      s_bracket_hi = s;
      break;
    }
    s_prev = s;
  }
  if (s_bf < kNever) {
    // Not missed: the engine's crossing is no later than the sample found outside.
    ASSERT_LE(s_engine, s_bracket_hi) << "missed crossing near s=" << s_bf;
    const double slope = std::abs(2 * A * s_bf + B);
    if (slope * S > 1e-4 * scale(s_bf)) {
      EXPECT_NEAR(s_engine, s_bf, 1e-9 * S);
    }
  }
  if (s_engine < kNever && s_engine > 0.0) {
    // Not spurious: q really is at zero there and not going down.
    EXPECT_LE(std::abs(q_of(A, B, C, s_engine)), 1e-10 * scale(s_engine));
    EXPECT_GE(2 * A * s_engine + B, -1e-7 * (std::abs(A) * S + std::abs(B)));
  }
  if (s_engine == 0.0 && C < 0.0) ADD_FAILURE() << "crossing reported now while inside";
}

TEST(FirstUpwardCrossing, RandomQuadratics) {
  Rng rng(3);
  for (int trial = 0; trial < 3000; ++trial) {
    const double A = (rng.uniform() < 0.5 ? -1 : 1) * std::pow(10.0, rng.uniform(-3, 2));
    const double B = (rng.uniform() < 0.5 ? -1 : 1) * std::pow(10.0, rng.uniform(-3, 2));
    const double C = -std::pow(10.0, rng.uniform(-6, 1));
    check_quadratic({A, B, C}, "random", trial);
  }
}

// Wall under gravity: gap h(s) = h0 + v_n s + g_n s^2 / 2, contact when h falls through zero,
// so q = -h. Cell faces: x(s) - x_face with gravity along the axis.
TEST(FirstUpwardCrossing, WallsAndCellFacesUnderGravity) {
  Rng rng(4);
  for (int trial = 0; trial < 3000; ++trial) {
    const double gap = rng.uniform(0, 1.0) * (rng.uniform() < 0.1 ? 1e-9 : 1.0);
    const double vn = rng.uniform(-3, 3);
    const double gn = rng.uniform() < 0.2 ? 0.0 : rng.uniform(-10, 10);
    check_quadratic({-0.5 * gn, -vn, -gap}, "wall", trial);
  }
}

// Linear motion (no gravity) and B = 0 (starting at rest under gravity).
TEST(FirstUpwardCrossing, LinearAndFromRest) {
  Rng rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    check_quadratic({0.0, rng.uniform(-2, 2), -rng.uniform(0, 1)}, "linear", trial);
    check_quadratic({rng.uniform(-5, 5), 0.0, -rng.uniform(0, 1)}, "rest", trial);
  }
  EXPECT_EQ(first_upward_crossing(0.0, 0.0, -1.0), kNever);
  EXPECT_EQ(first_upward_crossing(0.0, -1.0, -1.0), kNever);
  EXPECT_DOUBLE_EQ(first_upward_crossing(0.0, 2.0, -1.0), 0.5);
  EXPECT_DOUBLE_EQ(first_upward_crossing(1.0, 0.0, -4.0), 2.0);
  EXPECT_EQ(first_upward_crossing(-1.0, 0.0, -4.0), kNever);
  // Touching (C = 0) at rest with q'' < 0: q(s) = -s^2 never comes above zero, so there is no
  // crossing (a sphere resting against a ceiling falls away under gravity).
  EXPECT_EQ(first_upward_crossing(-4.905, 0.0, 0.0), kNever);
  // Touching and moving outward: the crossing is now.
  EXPECT_EQ(first_upward_crossing(-4.905, 1.0, 0.0), 0.0);
}

// Near-tangent: a downward parabola whose maximum is just above or just below zero,
// q(s) = A (s - s_v)^2 + A s_v^2 (-delta) with A < 0: the maximum is |A| s_v^2 delta.
// Either answer is acceptable for |delta| at round-off; otherwise the engine must agree.
TEST(FirstUpwardCrossing, NearTangent) {
  Rng rng(6);
  for (int trial = 0; trial < 3000; ++trial) {
    const double A = -std::pow(10.0, rng.uniform(-2, 2));
    const double sv = std::pow(10.0, rng.uniform(-2, 1));
    const double delta = (rng.uniform() < 0.5 ? -1 : 1) * std::pow(10.0, rng.uniform(-14, -2));
    const double B = -2.0 * A * sv;
    const double C = A * sv * sv * (1.0 + delta);
    check_quadratic({A, B, C}, "tangent", trial);
  }
}

// Round-off overlap: C slightly positive.
TEST(FirstUpwardCrossing, AlreadyAcrossByRoundOff) {
  Rng rng(8);
  for (int trial = 0; trial < 2000; ++trial) {
    const double A = rng.uniform(-5, 5), B = rng.uniform(-2, 2), C = 1e-15 * rng.uniform();
    const double s = first_upward_crossing(A, B, C);
    if (B > 0) {
      EXPECT_EQ(s, 0.0) << "moving outward while already across: the crossing is now";
    } else if (A > 0) {
      // Falls back inside and comes out again: the later upward root.
      const double later = (-B + std::sqrt(B * B - 4 * A * C)) / (2 * A);
      EXPECT_NEAR(s, later, 1e-12 * (1 + later)) << "A=" << A << " B=" << B;
    } else {
      EXPECT_EQ(s, kNever) << "A=" << A << " B=" << B;
    }
  }
}

// Pair prediction on random approaches, many of them grazing (impact parameter within 1e-12..1
// of the contact distance) and some already touching.
// Checks (tolerance 1e-10 of the contact distance: the overlap the engine promises never to
// exceed; round-off of the closed form is ~1e-15 of |dr|^2/contact):
//  - if a time is returned, the distance there is the contact distance and the pair approaches;
//  - no overlap deeper than 1e-10 contact happens before the returned time (or at all, if none).
TEST(SphereContactTime, AgainstConservativeAdvancement) {
  Rng rng(9);
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double contact = std::pow(10.0, rng.uniform(-2, 1));
    Vec3 dr = rng.normal3().normalized() * contact * (1.0 + std::pow(10.0, rng.uniform(-12, 1)));
    // Aim the relative velocity at the impact parameter b (grazing when b ~ contact).
    const double b = contact * (rng.uniform() < 0.5 ? rng.uniform(0, 1.2)
                                                    : 1.0 + (rng.uniform() < 0.5 ? -1 : 1) *
                                                                std::pow(10.0, rng.uniform(-12, -3)));
    Vec3 side = dr.cross(rng.normal3()).normalized();
    const double along = std::sqrt(std::max(0.0, dr.squaredNorm() - b * b));
    const Vec3 target = side * b;  // closest approach point relative to j
    Vec3 dv = (target - dr).normalized() * std::pow(10.0, rng.uniform(-2, 2));
    if (along == 0.0 || rng.uniform() < 0.1) dv = rng.normal3();  // some arbitrary directions
    const double s_engine = sphere_contact_time(dr, dv, contact);
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " |dr|/contact=" << dr.norm() / contact
                                      << " b/contact=" << b / contact << " s=" << s_engine);
    ASSERT_GE(s_engine, 0.0);
    auto distance = [&](double s) { return (dr + s * dv).norm(); };
    const double tol = 1e-10 * contact;
    // Conservative advancement to the first overlap deeper than tol.
    const double speed = dv.norm();
    const double s_max = (dr.norm() + contact) / speed;
    double s = 0.0, s_overlap = kNever;
    for (long it = 0; it < 2000000 && s <= s_max; ++it) {
      const double margin = distance(s) - contact + tol;
      if (margin <= 1e-3 * tol) {
        s_overlap = s;
        break;
      }
      s += margin / speed;
    }
    if (s_engine < kNever) {
      ++hits;
      EXPECT_NEAR(distance(s_engine), contact, tol) << "spurious contact";
      EXPECT_LE((dr + s_engine * dv).dot(dv), 1e-12 * dr.norm() * speed) << "not approaching";
      EXPECT_LE(s_engine, s_overlap) << "overlap before the predicted contact";
    } else {
      ++misses;
      EXPECT_EQ(s_overlap, kNever) << "missed contact: overlap at s=" << s_overlap;
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(misses, 500);
}

}  // namespace
}  // namespace carom
