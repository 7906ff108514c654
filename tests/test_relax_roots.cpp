// core/relax_flight.hpp and core/relax_roots.hpp against slow, obviously-correct references.
//
// - phi1, phi2: long-double series / closed forms. The flight: a fine long-double RK4
//   integration of dv/ds = drive - rate v.
// - Contact times: a brute-force scan of the gap function G(s) on a fine grid. A contact is
//   the first grid cell where G goes from > 0 to <= 0, refined by bisection; a dip shorter
//   than a cell is caught where G' goes from < 0 to > 0 inside a cell (its minimum, found by
//   bisection on G', is checked). The grids have 1e4 (3-D) and 1e5 (1-D) cells: far finer
//   than the flight's structure (at most a few extrema of G per horizon). Where a contact is
//   predicted at s_p the scan ends at min(horizon, 1.01 s_p + 1e-3 horizon): an earlier contact,
//   or none near s_p, is still caught, and the finer grid costs nothing.
// - Tolerances on times: 1e-9 of the case's time scale T (the horizon, or the time to cross
//   the contact distance if shorter), plus the conditioning of the root: G is known to
//   round-off delta_G ~ 1e-15 of the lengths involved, which moves a root by delta_G / |G'|.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <vector>

#include "contact_oracle.hpp"
#include "core/ballistic_flight.hpp"
#include "core/relax_roots.hpp"
#include "core/rng.hpp"
#include "core/roots.hpp"
#include "tests/random_draws.hpp"

namespace carom {
namespace {

using test::kEps;
using test::kGravityVector;
using test::log_uniform;
using test::random_flight;
using test::unit;

// --- phi functions and the flight ---------------------------------------------------------

long double phi1_reference(long double x) {
  if (x > 0.5L) return -std::expm1(-x) / x;
  long double term = 1.0L, sum = 0.0L;  // sum_n (-x)^n / (n+1)!
  for (int n = 0; n < 40; ++n) sum += term, term *= -x / (n + 2);
  return sum;
}
long double phi2_reference(long double x) {
  if (x > 0.5L) return (x + std::expm1(-x)) / (x * x);
  long double term = 0.5L, sum = 0.0L;  // sum_n (-x)^n / (n+2)!
  for (int n = 0; n < 40; ++n) sum += term, term *= -x / (n + 3);
  return sum;
}

// phi1 = -expm1(-x)/x is a few ulps everywhere. phi2's closed form (used for x >= 1e-3) loses
// digits to the cancellation in x + expm1(-x) ~ x^2/2: relative error about 2 eps / x, so the
// tolerance is 4 eps (1 + 1/x) (9e-13 at x = 1e-3; the series below 1e-3 is good to 1e-18).
TEST(RelaxPhi, MatchesLongDoubleReference) {
  std::vector<double> xs{0.0, 1e-300, 1e-12, 9.99e-5, 1e-4, 1.001e-4, 9.99e-4, 1e-3, 1.001e-3};
  Rng rng(11);
  for (int k = 0; k < 20000; ++k)
    xs.push_back(k % 2 ? rng.uniform(0.0, 50.0) : log_uniform(rng, 1e-12, 50.0));
  double worst1 = 0.0, worst2 = 0.0;
  for (double x : xs) {
    const double e1 =
        std::abs(relax_phi1(x) - double(phi1_reference(x))) / double(phi1_reference(x));
    const double e2 =
        std::abs(relax_phi2(x) - double(phi2_reference(x))) / double(phi2_reference(x));
    EXPECT_LE(e1, 4.0 * kEps) << "x = " << x;
    EXPECT_LE(e2, 4.0 * kEps * (1.0 + 1.0 / std::max(x, 1e-3))) << "x = " << x;
    worst1 = std::max(worst1, e1);
    worst2 = std::max(worst2, e2);
  }
  std::printf("[ relax ] phi1 worst relative error %.2e, phi2 %.2e\n", worst1, worst2);
}

// rate = 0 is the ballistic parabola bit for bit (the same expressions in a different order
// that rounds identically), so relax and ballistic runs agree exactly without drag.
TEST(RelaxPhi, ZeroRateIsTheBallisticParabolaExactly) {
  Rng rng(12);
  const BallisticFlight ballistic{kGravityVector};
  const RelaxFlight relax{0.0, kGravityVector};
  for (int k = 0; k < 1000; ++k) {
    const Vec3 v0 = rng.normal3();
    const double s = log_uniform(rng, 1e-9, 1.0);
    EXPECT_EQ(relax.displacement(v0, s), ballistic.position(Vec3::Zero(), v0, s));
    EXPECT_EQ(relax.velocity(v0, s), ballistic.velocity(v0, s));
  }
}

// Against RK4 in long double with steps of at most 1e-3 of tau and of s (truncation error
// ~(rate h)^4 / 120 per unit time scale, far below 1e-12): relative 1e-9 of the scale
// |v0| s + |a0| s^2 (displacement) and |v0| + |a0| s (velocity).
TEST(RelaxFlight, MatchesFineRk4Integration) {
  Rng rng(13);
  for (int k = 0; k < 40; ++k) {
    const double rate = k % 5 == 0 ? 0.0 : log_uniform(rng, 1.0, 1e4);
    const RelaxFlight f{rate, kGravityVector + rate * log_uniform(rng, 0.01, 10.0) * unit(rng)};
    const Vec3 v0 = log_uniform(rng, 0.01, 10.0) * unit(rng);
    const double s = log_uniform(rng, 1e-5, 1e-2);
    const int steps = int(std::ceil(std::max(1e3, 1e3 * rate * s)));
    const long double h = (long double)s / steps;
    Eigen::Matrix<long double, 3, 1> r = Eigen::Matrix<long double, 3, 1>::Zero();
    Eigen::Matrix<long double, 3, 1> v = v0.cast<long double>();
    const Eigen::Matrix<long double, 3, 1> drive = f.drive.cast<long double>();
    const long double k_rate = rate;
    auto acc = [&](const Eigen::Matrix<long double, 3, 1>& w) {
      return (drive - k_rate * w).eval();
    };
    for (int i = 0; i < steps; ++i) {
      const auto k1v = acc(v), k1r = v;
      const auto k2v = acc(v + 0.5L * h * k1v), k2r = (v + 0.5L * h * k1v).eval();
      const auto k3v = acc(v + 0.5L * h * k2v), k3r = (v + 0.5L * h * k2v).eval();
      const auto k4v = acc(v + h * k3v), k4r = (v + h * k3v).eval();
      r += h / 6.0L * (k1r + 2.0L * k2r + 2.0L * k3r + k4r);
      v += h / 6.0L * (k1v + 2.0L * k2v + 2.0L * k3v + k4v);
    }
    const double a0 = f.acceleration(v0).norm();
    EXPECT_LE((f.displacement(v0, s) - r.cast<double>()).norm(),
              1e-9 * (v0.norm() * s + a0 * s * s));
    EXPECT_LE((f.velocity(v0, s) - v.cast<double>()).norm(), 1e-9 * (v0.norm() + a0 * s));
  }
}

// The gas work booked for a relax flight (move_booking_gas_work) against the integral of the
// gas force's power (a(v) - g) . v along a fine long-double RK4 integration of the same flight
// (power integrated by Simpson's rule on the RK4 nodes: error ~h^4, far below the 1e-9 asked).
// Reference scale: |a - g| |v| s, the work's natural size. The move itself must be bit for bit
// displacement() and velocity(): the engine's trajectories do not change by booking.
TEST(RelaxFlight, GasWorkIsTheIntegralOfTheGasForcesPower) {
  using V = Eigen::Matrix<long double, 3, 1>;
  Rng rng(17);
  for (int k = 0; k < 40; ++k) {
    const double rate = k % 5 == 0 ? 0.0 : log_uniform(rng, 1.0, 1e4);
    const RelaxFlight f{rate, kGravityVector + rate * log_uniform(rng, 0.01, 10.0) * unit(rng) +
                                  log_uniform(rng, 0.1, 10.0) * unit(rng)};
    const Vec3 v0 = log_uniform(rng, 0.01, 10.0) * unit(rng);
    const double s = log_uniform(rng, 1e-5, 1e-2);
    const int steps = 2 * int(std::ceil(std::max(1e3, 1e3 * rate * s)));
    const long double h = (long double)s / steps;
    const V drive = f.drive.cast<long double>(), g = kGravityVector.cast<long double>();
    const long double k_rate = rate;
    auto acc = [&](const V& w) { return (drive - k_rate * w).eval(); };
    auto power = [&](const V& w) { return (acc(w) - g).dot(w); };
    V v = v0.cast<long double>();
    long double integral = power(v);
    for (int i = 1; i <= steps; ++i) {
      const V k1 = acc(v), k2 = acc(v + 0.5L * h * k1), k3 = acc(v + 0.5L * h * k2),
              k4 = acc(v + h * k3);
      v += h / 6.0L * (k1 + 2.0L * k2 + 2.0L * k3 + k4);
      integral += (i == steps ? 1.0L : (i % 2 == 1 ? 4.0L : 2.0L)) * power(v);
    }
    integral *= h / 3.0L;
    Vec3 r{0.1, -0.2, 0.3}, u = v0;
    const double work = f.move_booking_gas_work(r, u, s, kGravityVector);
    const double scale =
        (f.acceleration(v0) - kGravityVector).norm() * (v0.norm() + f.acceleration(v0).norm() * s) * s;
    EXPECT_NEAR(work, (double)integral, 1e-9 * scale) << "case " << k;
    EXPECT_EQ(r, Vec3(Vec3{0.1, -0.2, 0.3} + f.displacement(v0, s)));
    EXPECT_EQ(u, f.velocity(v0, s));
  }
}

// reach_bound ends most candidates of a relax pair prediction (relax_collision) before any
// exponential is computed, so it must never fall short of where the flight goes: over random
// flights (rates 0 to 1e4 1/s, drives and velocities over three decades, towards and against
// the velocity) it must cover the distance |r(s') - r0| at 200 times s' in [0, s] (the exact
// flight, checked above), and the Euclidean form |v0| s + |a0| s^2 / 2 of relax_pair_time's own
// first rejection, which the engine's looser test must never reject more than. The sum of
// magnitudes is mathematically never below the length; computed, it may fall short of the
// computed length by round-off only (when one component holds the whole vector), which the
// engine covers with a relative margin of 1e-12: checked here with 1e-14.
TEST(RelaxFlight, ReachBoundCoversTheFlight) {
  Rng rng(19);
  for (int k = 0; k < 400; ++k) {
    const double rate = k % 5 == 0 ? 0.0 : log_uniform(rng, 1.0, 1e4);
    const RelaxFlight f{rate, kGravityVector + rate * log_uniform(rng, 0.01, 10.0) * unit(rng)};
    // Every eighth velocity along one axis: there the sum of magnitudes is the length itself.
    const Vec3 v0 = k % 8 == 3 ? Vec3(0, 0, -log_uniform(rng, 0.01, 10.0))
                               : Vec3(log_uniform(rng, 0.01, 10.0) * unit(rng));
    const double s = log_uniform(rng, 1e-5, 1e-1);
    const double bound = f.reach_bound(v0, s);
    const double euclidean = s * (v0.norm() + 0.5 * s * f.acceleration(v0).norm());
    EXPECT_GE(bound, euclidean * (1.0 - 1e-14)) << "case " << k;
    double farthest = 0.0;
    for (int m = 1; m <= 200; ++m)
      farthest = std::max(farthest, f.displacement(v0, s * m / 200).norm());
    EXPECT_GE(bound, farthest * (1.0 - 1e-14)) << "case " << k;
  }
}

// RelaxFlightBounds lets a prediction bound a candidate's reach from its velocity alone: for a
// set of random flights, the set's bound must never fall below any member's own reach_bound
// (|drive - rate v| <= |drive| + rate |v| for sums of magnitudes; margin as above).
TEST(RelaxFlight, BoundsOfASetCoverEveryMember) {
  Rng rng(23);
  std::vector<RelaxFlight> flights;
  RelaxFlightBounds bounds;
  for (int k = 0; k < 50; ++k) {
    const double rate = k % 5 == 0 ? 0.0 : log_uniform(rng, 1.0, 1e4);
    flights.push_back(
        RelaxFlight{rate, kGravityVector + rate * log_uniform(rng, 0.01, 10.0) * unit(rng)});
    bounds.include(flights.back());
  }
  for (int k = 0; k < 400; ++k) {
    const Vec3 v0 = log_uniform(rng, 0.01, 10.0) * unit(rng);
    const double s = log_uniform(rng, 1e-5, 1e-1);
    const double bound = bounds.reach_bound(v0, s);
    for (const RelaxFlight& f : flights)
      ASSERT_GE(bound, f.reach_bound(v0, s) * (1.0 - 1e-14)) << k;
  }
}

// --- the brute-force oracle (contact_oracle.hpp) --------------------------------------------

using test::Agreement;
using test::brute_force_contact;
using test::compare;
using test::GapFunction;
using test::Sample;

// --- 1-D gaps --------------------------------------------------------------------------------

struct GapCase {
  double gap, speed, drive, rate, horizon;
};

// The gap as relax_roots.hpp defines it (a component of a relax flight, checked above).
GapFunction gap_function(const GapCase& c) {
  const double a0 = c.drive - c.rate * c.speed;
  return [=](double s) {
    return Sample{c.gap + c.speed * s + a0 * s * s * relax_phi2(c.rate * s),
                  c.speed + a0 * s * relax_phi1(c.rate * s)};
  };
}

void check_gap(Agreement& stats, const GapCase& c, const char* family, int trial) {
  const GapFunction G = gap_function(c);
  const double predicted = relax_gap_closing_time(c.gap, c.speed, c.drive, c.rate, c.horizon);
  const double end =
      predicted == kNever ? c.horizon : std::min(c.horizon, predicted * 1.01 + 1e-3 * c.horizon);
  const double brute = brute_force_contact(G, end, 100000);
  // Conditioning: gap is known to ~4 eps of its terms' size L; a root moves by that / |gap'|.
  const double a0 = std::abs(c.drive - c.rate * c.speed);
  const double L = std::abs(c.gap) + std::abs(c.speed) * c.horizon + a0 * c.horizon * c.horizon;
  const double slope = brute == kNever ? 1.0 : std::max(std::abs(G(brute).slope), 1e-300);
  compare(stats, G, predicted, brute, 1e-9 * c.horizon + 16.0 * kEps * L / slope, L, family, trial);
}

// Random 1-D cases in five families: anything; a closing gap that turns around (a minimum)
// near zero, just above or below it; an opening gap pulled back (closes after a maximum);
// a root placed next to the horizon (cut-off just before or after it); long horizons (to 10 s).
TEST(RelaxGap, AgreesWithBruteForceScan) {
  Rng rng(21);
  Agreement stats;
  for (int trial = 0; trial < 600; ++trial) {
    GapCase c;
    c.rate = trial % 3 == 0 ? 0.0 : log_uniform(rng, 1.0, 1e4);
    const int family = trial % 5;
    c.horizon = family == 4 ? log_uniform(rng, 1e-2, 10.0) : log_uniform(rng, 1e-5, 1e-2);
    const double speed = log_uniform(rng, 1e-3, 10.0);
    c.gap = log_uniform(rng, 1e-9, 1e-2);
    c.speed = (rng.uniform() < 0.5 ? -1.0 : 1.0) * speed;
    c.drive = (rng.uniform() < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 0.1, 1e5);
    if (family == 1 || family == 2) {
      // Family 1: closing, then turned back by the drive (a minimum at `turn`); its value is set
      // to +-1e-6..1e-2 of the scale |speed| turn (miss or hit), the horizon around the turn.
      // Family 2: opening, then pulled back (a maximum); the horizon beyond the turn.
      c.speed = family == 1 ? -speed : speed;
      c.drive = (family == 1 ? 1.0 : -1.0) * log_uniform(rng, 0.1, 1e5);
      const RelaxFlight f{c.rate, Vec3(c.drive, 0.0, 0.0)};
      const Vec3 v0(c.speed, 0.0, 0.0);
      auto same_sign = [&](double s) { return f.velocity(v0, s).x() * c.speed > 0.0; };
      double lo = 0.0, hi = 1e-2;
      if (!same_sign(hi)) {
        while (hi - lo > 1e-15 * hi) (same_sign(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
        const double turn = hi;
        if (family == 1) {
          c.horizon = turn * rng.uniform(0.5, 3.0);
          const double extremum =
              (rng.uniform() < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-6, 1e-2) * speed * turn;
          c.gap = extremum - f.displacement(v0, turn).x();
        } else {
          c.horizon = turn * rng.uniform(1.0, 10.0);
        }
      }
    }
    if (family == 3) {
      const double root = brute_force_contact(gap_function(c), c.horizon, 2000);
      if (root != kNever) c.horizon = root * (1.0 + (rng.uniform() < 0.5 ? -1.0 : 1.0) * 1e-7);
    }
    if (!(c.gap > 0.0)) c.gap = 1e-9;
    check_gap(stats, c, "gap", trial);
  }
  std::printf("[ relax ] gap: %d cases, %d contacts, worst error %.2g of tolerance\n", stats.cases,
              stats.hits, stats.worst_error);
  EXPECT_GT(stats.hits, 100);
  EXPECT_GT(stats.misses, 100);
}

// Touching cases decided by the rules, not by a scan.
TEST(RelaxGap, TouchingRules) {
  EXPECT_EQ(relax_gap_closing_time(0.0, -1.0, 0.0, 10.0, 1e-3), 0.0);      // touching, closing
  EXPECT_EQ(relax_gap_closing_time(-1e-18, -1.0, 5.0, 0.0, 1e-3), 0.0);    // overlap, closing
  EXPECT_EQ(relax_gap_closing_time(0.0, 0.0, -9.81, 0.0, 1e-3), 0.0);      // at rest, pulled in
  EXPECT_EQ(relax_gap_closing_time(0.0, 0.0, 9.81, 100.0, 1e-3), kNever);  // at rest, pushed out
  EXPECT_EQ(relax_gap_closing_time(0.0, 1.0, 9.81, 100.0, 1e-3), kNever);  // leaving for good
  EXPECT_EQ(relax_gap_closing_time(1e-3, 0.0, 0.0, 0.0, 1.0), kNever);     // nothing moves
  // Leaving but pulled back: closes at the ballistic return time 2 v / g (rate 0).
  EXPECT_NEAR(relax_gap_closing_time(0.0, 1.0, -9.81, 0.0, 1.0), 2.0 / 9.81, 1e-15);
  // Overlapping by round-off, leaving slowly and turned back before it gets out: at the turn.
  EXPECT_NEAR(relax_gap_closing_time(-1e-12, 1e-9, -9.81, 0.0, 1.0), 1e-9 / 9.81, 1e-22);
}

// --- pairs -----------------------------------------------------------------------------------

struct PairCase {
  Vec3 dr, va, vb;
  RelaxFlight fa, fb;
  double contact, horizon;
};

GapFunction pair_function(const PairCase& c) {
  return [=](double s) {
    const Vec3 r = c.dr + c.fa.displacement(c.va, s) - c.fb.displacement(c.vb, s);
    const Vec3 u = c.fa.velocity(c.va, s) - c.fb.velocity(c.vb, s);
    return Sample{r.norm() - c.contact, r.dot(u) / r.norm()};
  };
}

// Random pair kinematics; dr set by the family.
PairCase random_pair(Rng& rng, int family) {
  PairCase c;
  c.contact = log_uniform(rng, 5e-5, 5e-3) + log_uniform(rng, 5e-5, 5e-3);
  c.va = log_uniform(rng, 0.01, 10.0) * unit(rng);
  c.vb = log_uniform(rng, 0.01, 10.0) * unit(rng);
  c.fa = random_flight(rng, 0.2);
  c.fb = random_flight(rng, 0.2);
  c.horizon = family == 4 ? log_uniform(rng, 1e-2, 1.0) : log_uniform(rng, 1e-5, 1e-2);
  const double t = rng.uniform(0.02, 1.2) * c.horizon;  // when the constructed event happens
  const Vec3 shift = c.fa.displacement(c.va, t) - c.fb.displacement(c.vb, t);
  const Vec3 u = c.fa.velocity(c.va, t) - c.fb.velocity(c.vb, t);
  const Vec3 a =
      c.fa.acceleration(c.fa.velocity(c.va, t)) - c.fb.acceleration(c.fb.velocity(c.vb, t));
  Vec3 n = unit(rng);
  if (family == 0 || family == 4) {  // aimed: in contact and approaching at t (an earlier
                                     // contact may come first); 4: long horizons
    if (n.dot(u) > 0.0) n = -n;
    c.dr = c.contact * n - shift;
  } else if (family == 1 || family == 2) {
    // Closest approach at t at the distance contact (1 +- delta): n perpendicular to u and to
    // the relative acceleration, so d' = 0 and d'' = |u|^2 / |r| > 0 there (a true minimum).
    // Family 2 is near-tangent: a hit at a shallow angle (n tilted towards -u by 1e-4..1e-1).
    Vec3 e = u.cross(a);
    if (e.norm() < 1e-9 * u.norm() * a.norm() || e.norm() == 0.0) e = u.cross(unit(rng));
    n = e.normalized();
    if (family == 1) {
      const double delta = (rng.uniform() < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-6, 1e-3);
      c.dr = c.contact * (1.0 + delta) * n - shift;
    } else {
      n = (n - log_uniform(rng, 1e-4, 1e-1) * u.normalized()).normalized();
      c.dr = c.contact * n - shift;
    }
  } else {  // anywhere within reach
    c.dr =
        (c.contact + rng.uniform(0.0, 2.0) * (u.norm() + c.va.norm() + c.vb.norm()) * c.horizon) *
        n;
  }
  return c;
}

// Time scale of a pair: the horizon, or the time to cross the contact distance if shorter.
double pair_time_scale(const PairCase& c) {
  const double speed =
      std::max({(c.va - c.vb).norm(),
                (c.fa.velocity(c.va, c.horizon) - c.fb.velocity(c.vb, c.horizon)).norm()});
  return std::min(c.horizon, c.contact / speed);
}

// >= 2000 random pairs with unequal relaxation times, in five families (aimed, grazing within
// 1e-6..1e-3 of contact hitting or missing, near-tangent hits, anywhere, aimed with horizons of
// 0.01..1 s). Tolerance 1e-9 of the
// time scale plus the conditioning of the root (positions known to ~16 eps of their size).
TEST(RelaxPair, AgreesWithBruteForceScan) {
  Rng rng(31);
  const char* names[] = {"aimed", "graze", "tangent", "anywhere", "long"};
  Agreement stats[5];
  std::vector<PairCase> cases;
  long iterations = 0;
  int most_iterations = 0;
  const std::uint64_t caps_before = relax_contact_cap_hits();
  for (int trial = 0; trial < 2750; ++trial) {
    const int family = trial % 5;
    const PairCase c = random_pair(rng, family);
    const GapFunction G = pair_function(c);
    if (!(G(0.0).value > 0.0)) continue;  // constructed overlapping: not this test's business
    cases.push_back(c);
    const RelaxContactSearch search =
        relax_pair_contact_search(c.dr, c.va, c.fa, c.vb, c.fb, c.contact, c.horizon);
    iterations += search.iterations;
    most_iterations = std::max(most_iterations, search.iterations);
    const double end = search.time == kNever
                           ? c.horizon
                           : std::min(c.horizon, search.time * 1.01 + 1e-3 * c.horizon);
    const double brute = brute_force_contact(G, end, 10000);
    const double length = c.dr.norm() + c.contact + (c.va.norm() + c.vb.norm()) * c.horizon;
    const double slope = brute == kNever ? 1.0 : std::max(std::abs(G(brute).slope), 1e-300);
    compare(stats[family], G, search.time, brute,
            1e-9 * pair_time_scale(c) + 16.0 * kEps * length / slope, c.contact, names[family],
            trial);
  }
  for (int f = 0; f < 5; ++f) {
    std::printf(
        "[ relax ] pairs %-8s: %d cases, %d contacts, %d misses, worst error %.2g of tolerance\n",
        names[f], stats[f].cases, stats[f].hits, stats[f].misses, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 10) << names[f];
  }
  EXPECT_GT(stats[1].misses, 100);  // grazes that miss are there
  std::printf("[ relax ] pair search iterations: mean %.2f, max %d over %zu pairs\n",
              double(iterations) / cases.size(), most_iterations, cases.size());
  EXPECT_EQ(relax_contact_cap_hits(), caps_before);
  // Cost of the prediction alone (no assertion: shared machines).
  const auto start = std::chrono::steady_clock::now();
  double sink = 0.0;
  for (int repeat = 0; repeat < 5; ++repeat)
    for (const PairCase& c : cases) {
      const double s = relax_pair_contact_time(c.dr, c.va, c.fa, c.vb, c.fb, c.contact, c.horizon);
      sink += s == kNever ? 0.0 : s;
    }
  const double ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ relax ] pair prediction: %.0f ns per call (checksum %g)\n",
              ns / (5.0 * cases.size()), sink);
}

// rate 0 for both under the same gravity: the relative motion is linear, so the contact time
// is sphere_contact_time's (1e-12 of the time scale, both being round-off accurate, plus the
// conditioning of each computation).
TEST(RelaxPair, BallisticLimitMatchesSphereContactTime) {
  Rng rng(32);
  int contacts = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    PairCase c = random_pair(rng, 3);
    c.fa = c.fb = RelaxFlight{0.0, kGravityVector};
    // Two in three aimed at contact at t in [0, 1.2 horizon], the rest anywhere nearby.
    const Vec3 u = c.va - c.vb;
    Vec3 n = unit(rng);
    if (n.dot(u) > 0.0) n = -n;
    c.dr = trial % 3 ? Vec3(c.contact * n - rng.uniform(0.0, 1.2) * c.horizon * u)
                     : Vec3((c.contact * (1.0 + rng.uniform(1e-3, 2.0))) * unit(rng));
    const double linear = sphere_contact_time(c.dr, c.va - c.vb, c.contact);
    const double reference = linear <= c.horizon ? linear : kNever;
    const double predicted =
        relax_pair_contact_time(c.dr, c.va, c.fa, c.vb, c.fb, c.contact, c.horizon);
    if (reference == kNever) {
      EXPECT_EQ(predicted, kNever) << trial;
      continue;
    }
    ++contacts;
    // Conditioning. Here: the distance is known to ~16 eps of the lengths in it (dr and the
    // two displacements); a root moves by that / w, w the closing speed at contact. The
    // reference: its discriminant b^2 - v^2 c cancels down to (contact w)^2, which costs
    // about eps t |dr| |dv| / (contact w) (far-away pairs lose digits).
    const Vec3 r = c.dr + reference * u;
    const double length = c.dr.norm() + (c.va.norm() + c.vb.norm()) * reference;
    const double w = std::abs(r.dot(u)) / r.norm();
    const double scale = std::min(c.horizon, c.contact / u.norm());
    const double tolerance = 1e-12 * scale + 16.0 * kEps * length / w +
                             4.0 * kEps * reference * c.dr.norm() * u.norm() / (c.contact * w);
    EXPECT_NEAR(predicted, reference, tolerance) << trial;
  }
  EXPECT_GT(contacts, 100);
}

// Touching pairs: approaching returns 0; separating does not (kNever, or the return contact
// when the relative acceleration brings the pair back).
TEST(RelaxPair, TouchingRules) {
  const RelaxFlight ballistic{0.0, kGravityVector}, dragged{1e3, kGravityVector + 1e3 * Vec3(0, 0, 2.0)};
  const Vec3 up(0, 0, 1), zero = Vec3::Zero();
  const double contact = 1e-3;
  EXPECT_EQ(
      relax_pair_contact_time(contact * up, -0.1 * up, ballistic, zero, ballistic, contact, 1e-3),
      0.0);
  EXPECT_EQ(relax_pair_contact_time((contact - 1e-18) * up, -0.1 * up, dragged, zero, ballistic,
                                    contact, 1e-3),
            0.0);
  EXPECT_EQ(
      relax_pair_contact_time(contact * up, 0.1 * up, ballistic, zero, ballistic, contact, 1e-2),
      kNever);
  // a (on top) leaves upward at 0.01 m/s under gravity, b is carried upward by the gas: a
  // comes back down onto b. Brute force gives the time.
  PairCase c{contact * up, 0.01 * up, zero, ballistic, dragged, contact, 1e-2};
  const double predicted =
      relax_pair_contact_time(c.dr, c.va, c.fa, c.vb, c.fb, c.contact, c.horizon);
  const double brute = brute_force_contact(pair_function(c), c.horizon, 100000);
  ASSERT_NE(brute, kNever);
  EXPECT_GT(predicted, 0.0);
  EXPECT_NEAR(predicted, brute, 1e-9 * c.horizon);
  // Both at rest, touching side by side, the same flight: never.
  EXPECT_EQ(
      relax_pair_contact_time(contact * Vec3(1, 0, 0), zero, dragged, zero, dragged, contact, 1e-2),
      kNever);
}

// The bounds must hold over the whole step, not just at its start: here the relative
// acceleration pushes the pair apart at first (a's gas push, 100 m/s^2, decays in 0.1 ms) and
// then b's steady 10 m/s^2 wins, so the pair comes back after ~2 ms. A search that trusted
// the curvature at the start of a step would report no contact. Oracle: the scan (1e5 cells).
TEST(RelaxPair, AccelerationThatReversesBringsThePairBack) {
  const double contact = 1e-3;
  for (double start : {0.0, 1e-6, 1e-4}) {
    PairCase c{(contact + start) * Vec3(0, 0, 1),
               Vec3::Zero(),
               Vec3::Zero(),
               RelaxFlight{1e4, 1e4 * Vec3(0, 0, 0.01)},
               RelaxFlight{0.0, Vec3(0, 0, 10.0)},
               contact,
               1e-2};
    const double predicted =
        relax_pair_contact_time(c.dr, c.va, c.fa, c.vb, c.fb, c.contact, c.horizon);
    const double brute = brute_force_contact(pair_function(c), c.horizon, 100000);
    ASSERT_NE(brute, kNever);
    EXPECT_NEAR(predicted, brute, 1e-9 * c.horizon) << "start gap " << start;
  }
}

// relax_pair_separating's promise: where it says the pair separates, the contact search ends
// with no contact at its first step. Pairs at contact (to 1e-13 .. 1e-3 of it, overlapping by
// as little, or exactly), separating along a random direction at random angles (from nearly
// tangential to head-on), under the five families' flights (unequal drag and drive, strong and
// weak) and horizons of 1e-5 .. 1 s; and the random pairs above. Both answers must be common,
// and it must answer most pairs that separate clearly faster than their accelerations allow
// (what it is for: resting contacts of a dense bed that part).
TEST(RelaxPair, SeparatingPairsEndTheSearchAtItsFirstStep) {
  Rng rng(41);
  int separating = 0, clear = 0, clear_found = 0, approaching = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    PairCase c = random_pair(rng, trial % 5);
    if (trial % 2 == 0) {
      // At contact, separating: the relative velocity at an angle to the normal.
      const Vec3 n = unit(rng);
      const double offset =
          trial % 8 == 0 ? 0.0 : (rng.uniform() < 0.5 ? -1.0 : 1.0) * log_uniform(rng, 1e-13, 1e-3);
      c.dr = c.contact * (1.0 + offset) * n;
      const Vec3 u = c.va - c.vb;
      const Vec3 tangent = (u - u.dot(n) * n).normalized();
      const double angle = rng.uniform(-1.5, 1.5);  // from the normal, rad
      c.vb = c.va - u.norm() * (std::cos(angle) * n + std::sin(angle) * tangent);
    }
    const bool says = relax_pair_separating(c.dr, c.va, c.fa, c.vb, c.fb, c.horizon);
    const RelaxContactSearch search =
        relax_pair_contact_search(c.dr, c.va, c.fa, c.vb, c.fb, c.contact, c.horizon);
    if (says) {
      ASSERT_EQ(search.time, kNever) << "trial " << trial << ": a separating pair touches";
      ASSERT_EQ(search.iterations, 1) << "trial " << trial;
      ++separating;
    }
    approaching += c.dr.dot(c.va - c.vb) < 0.0;
    // Clear: the normal speed is ten times what the accelerations can take away over the
    // horizon (|a_a| + |a_b| bounds the relative acceleration).
    const double slope = c.dr.normalized().dot(c.va - c.vb);
    const double turn =
        (c.fa.acceleration(c.va).norm() + c.fb.acceleration(c.vb).norm()) * c.horizon;
    if (slope > 10.0 * turn) {
      ++clear;
      clear_found += says;
    }
  }
  std::printf("separating %d, approaching %d, clearly separating %d (answered %d)\n", separating,
              approaching, clear, clear_found);
  EXPECT_GT(separating, 2000);
  EXPECT_GT(approaching, 10000);
  EXPECT_GT(clear, 1000);
  EXPECT_EQ(clear_found, clear) << "a pair that clearly separates was left to the search";
}

// --- the cylinder ----------------------------------------------------------------------------

// Random spheres inside a vertical tube: anywhere; near the axis (within 1e-6 of reach, or on
// it); near the wall (within 1e-9..1e-3 of reach) moving nearly tangentially. Oracle: the scan
// of G = reach - |rho| (1e4 cells), tolerance as for pairs with time scale reach / speed.
TEST(RelaxCylinder, AgreesWithBruteForceScan) {
  Rng rng(41);
  Agreement stats[3];
  const char* names[] = {"anywhere", "axis", "wall"};
  long iterations = 0;
  int most_iterations = 0, cases = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int family = trial % 3;
    const double reach = log_uniform(rng, 1e-3, 1e-1);
    const RelaxFlight f = random_flight(rng, 0.2);
    const double horizon = log_uniform(rng, 1e-5, 1e-2);
    Vec3 v = log_uniform(rng, 0.01, 10.0) * unit(rng);
    const double angle = rng.uniform(0.0, 6.283185307179586);
    const Vec3 radial(std::cos(angle), std::sin(angle), 0.0), tangent(-radial.y(), radial.x(), 0.0);
    double distance = reach * std::sqrt(rng.uniform());
    if (family == 1) distance = trial % 2 ? 0.0 : reach * log_uniform(rng, 1e-12, 1e-6);
    if (family == 2) {
      distance = reach * (1.0 - log_uniform(rng, 1e-9, 1e-3));
      const double speed = v.norm();
      v = speed * (tangent + rng.uniform(-1e-3, 1e-3) * radial).normalized() + Vec3(0, 0, v.z());
    }
    const Vec3 offset = distance * radial + Vec3(0, 0, rng.uniform(-1.0, 1.0));
    const GapFunction G = [&](double s) {
      const Vec3 r = offset + f.displacement(v, s), u = f.velocity(v, s);
      const double rho = r.head<2>().norm();
      return Sample{reach - rho,
                    rho > 0.0 ? -r.head<2>().dot(u.head<2>()) / rho : -u.head<2>().norm()};
    };
    const RelaxContactSearch search = relax_cylinder_contact_search(offset, v, f, reach, horizon);
    ++cases;
    iterations += search.iterations;
    most_iterations = std::max(most_iterations, search.iterations);
    const double end =
        search.time == kNever ? horizon : std::min(horizon, search.time * 1.01 + 1e-3 * horizon);
    const double brute = brute_force_contact(G, end, 10000);
    const double speed = std::max(v.head<2>().norm(), f.velocity(v, horizon).head<2>().norm());
    const double slope = brute == kNever ? 1.0 : std::max(std::abs(G(brute).slope), 1e-300);
    const double length = reach + speed * horizon;
    compare(stats[family], G, search.time, brute,
            1e-9 * std::min(horizon, reach / speed) + 16.0 * kEps * length / slope, reach,
            names[family], trial);
  }
  for (int f = 0; f < 3; ++f) {
    std::printf("[ relax ] cylinder %-8s: %d cases, %d contacts, worst error %.2g of tolerance\n",
                names[f], stats[f].cases, stats[f].hits, stats[f].worst_error);
    EXPECT_GT(stats[f].hits, 20) << names[f];
  }
  std::printf("[ relax ] cylinder search iterations: mean %.2f, max %d\n",
              double(iterations) / cases, most_iterations);
}

// As for pairs, a curvature that changes sign within a step: a sphere next to the wall,
// moving tangentially at 0.1 m/s (the wall's curvature brings it outward: G'' = -|u|^2 /
// reach), with an outward drift of 0.01 m/s that the gas brakes within 0.1 ms (an inward
// acceleration of 100 m/s^2 at first, which holds G'' > 0). Oracle: the scan.
TEST(RelaxCylinder, BrakedDriftThenTheWallsCurvature) {
  const double reach = 0.01;
  for (double start : {1e-9, 1e-7, 1e-6, 1e-5}) {
    const Vec3 offset((1.0 - start) * reach, 0.0, 0.0), v(0.01, 0.1, 0.0);
    const RelaxFlight f{1e4, 1e4 * Vec3(0.0, 0.1, 0.0)};  // terminal velocity (0, 0.1, 0)
    const double predicted = relax_cylinder_contact_time(offset, v, f, reach, 1e-2);
    const GapFunction G = [&](double s) {
      const Vec3 r = offset + f.displacement(v, s), u = f.velocity(v, s);
      const double rho = r.head<2>().norm();
      return Sample{reach - rho, -r.head<2>().dot(u.head<2>()) / rho};
    };
    const double brute = brute_force_contact(G, 1e-2, 100000);
    ASSERT_NE(brute, kNever);
    EXPECT_NEAR(predicted, brute, 1e-9 * 1e-2) << "start gap " << start;
  }
}

// At the wall: moving outward returns 0; moving inward does not (kNever without horizontal
// forces); at rest horizontally never touches.
TEST(RelaxCylinder, TouchingRules) {
  const RelaxFlight ballistic{0.0, kGravityVector};
  const double reach = 0.01;
  EXPECT_EQ(relax_cylinder_contact_time(Vec3(reach, 0, 0), Vec3(0.1, 0, 0), ballistic, reach, 1e-2),
            0.0);
  EXPECT_EQ(
      relax_cylinder_contact_time(Vec3(reach, 0, 0), Vec3(-0.1, 0, 0), ballistic, reach, 1e-2),
      kNever);
  EXPECT_EQ(
      relax_cylinder_contact_time(Vec3(0.5 * reach, 0, 3), Vec3(0, 0, 1), ballistic, reach, 1e-2),
      kNever);
  // Straight chord from the axis: reach / speed.
  EXPECT_NEAR(relax_cylinder_contact_time(Vec3::Zero(), Vec3(0, 2.0, 5.0), ballistic, reach, 1.0),
              reach / 2.0, 1e-15);
}

}  // namespace
}  // namespace carom
