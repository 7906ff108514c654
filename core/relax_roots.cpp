// Event times for relax flights: the earliest contact within a horizon, never missed.
//
// 1-D gaps (planes, cell faces). gap'(s) = v(s) relaxes monotonically from gap_speed towards
// gap_drive / rate, so it changes sign at most once, at a time known in closed form: gap(s) is
// monotone on at most two pieces. The closing root lies in the first piece that descends to
// zero; there gap is convex or concave throughout (gap'' = a0 e^{-rate s} keeps its sign), so
// Newton from the matching end of the bracket converges monotonically; a bisection safeguard
// covers round-off and slow starts.
//
// Spheres and the cylinder: conservative advancement on a gap function G(s) (zero at contact,
// positive before) with a lower bound G'' >= -K valid from the current time s to the horizon.
// Then G(s + h) >= G + G' h - K h^2 / 2, and stepping to the first root of that parabola can
// never pass a contact. Approaching (G' < 0) this is a Newton step shortened by the curvature
// bound (quadratic convergence onto a hit); separating, the parabola still allows G to come
// back, which is what bounds the steps past a graze. When G' >= 0 the step allows a dip of the
// touching tolerance below zero, so a touch at rest (G = G' = 0) cannot stall the search.
// K alone is pessimistic when the acceleration is large but not along the normal (pairs
// sliding past each other in a strong drag): the steps then use G''(s + tau) >= c - J tau as
// well, with c the exact normal part of G'' at s and J a bound on how fast it can change
// (safe_step); this cuts the worst iteration counts by about four.
//  - Pair: G = |dr| - contact, G' = n.u, G'' = |u_perp|^2 / |dr| + n.a >= n.a >= -|a_rel|. The
//    curvature term only helps (straight-line relative motion makes G convex), so K is a bound
//    on the relative acceleration alone: a_rel(t) = a_a(s) e^{-k_a (t-s)} - a_b(s) e^{-k_b (t-s)}
//    is affine in the two decay factors, so |a_rel| is largest at one of the four corners
//    {a_a(s), a_a(H)} - {a_b(s), a_b(H)}; for (nearly) equal rates the tighter bound is
//    |a_a(s) - a_b(s)| + min |a(s)| min(1, |k_a - k_b| (H - s)). c = n.a_rel(s);
//    J = V K / contact + k_a |a_a| + k_b |a_b| bounds d(n.a_rel)/dt (|n'| <= V / |dr|).
//  - Cylinder: with rho the horizontal offset, G = (reach^2 - |rho|^2) / (2 reach) (= the gap
//    reach - |rho| near the wall), G' = -rho.u / reach, G'' = -(|u|^2 + rho.a) / reach >=
//    -(V^2 + reach A) / reach while inside. V: |u| is largest at an end of the segment
//    [v(s), v(H)] on which the velocity stays; A = |a(s)| (the acceleration only decays).
//    c = G''(s), J = A (3 V + rate reach) / reach. This
//    form has no singularity on the axis (the curvature of reach - |rho| grows without bound
//    there) and is tight for tangential motion near the wall.
#include "relax_roots.hpp"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <limits>

#include "contact_search.hpp"

namespace carom {
namespace contact_search {

namespace {
std::atomic<std::uint64_t> cap_hits{0};
}  // namespace

void count_cap_hit() {
  cap_hits.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace contact_search

namespace {

using contact_search::corner_bound;
using contact_search::earliest_contact;
using contact_search::flight_point;
using contact_search::FlightPoint;
using contact_search::kEpsilon;
using contact_search::kTouchingTolerance;
using contact_search::Probe;

/// Bound on |a_a(t) - a_b(t)| for t in [s, horizon], from the accelerations at s and at the
/// horizon of two flights with decay rates rate_a, rate_b; remaining = horizon - s.
double relative_acceleration_bound(const Vec3& a_now, const Vec3& a_end, double rate_a,
                                   const Vec3& b_now, const Vec3& b_end, double rate_b,
                                   double remaining) {
  // Corners: a_rel is affine in (e^{-rate_a (t-s)}, e^{-rate_b (t-s)}), |a_rel| convex.
  const double corners = corner_bound(a_now, a_end, b_now, b_end);
  // Difference: a_rel = e^{-rate_a tau} (a - b) + b (e^{-rate_a tau} - e^{-rate_b tau}) (or the
  // same with a and b swapped), and |e^{-x} - e^{-y}| <= min(1, |x - y|). Tight for equal
  // rates, where the corners are not: a_rel then only decays.
  const double mismatch = std::min(1.0, std::abs(rate_a - rate_b) * remaining);
  const double difference =
      (a_now - b_now).norm() +
      mismatch * std::sqrt(std::min(a_now.squaredNorm(), b_now.squaredNorm()));
  return std::min(corners, difference);
}

/// gap(s) and gap'(s) of a 1-D relax gap.
struct Gap {
  double gap0, speed0, a0, rate;
  double at(double s) const { return gap0 + speed0 * s + a0 * s * s * relax_phi2(rate * s); }
  double slope(double s) const { return speed0 + a0 * s * relax_phi1(rate * s); }
};

/// The root of a gap that decreases on [lo, hi] from gap(lo) > 0 to gap(hi) <= 0: Newton from
/// the end where it converges monotonically (lo if convex, hi if concave), with bisection
/// where a Newton step leaves the bracket or three steps have not halved it.
double closing_root(const Gap& g, double lo, double hi) {
  double x = g.a0 >= 0.0 ? lo : hi;
  double value = g.at(x);
  double width_checked = hi - lo;
  for (int iteration = 1; iteration <= 200; ++iteration) {
    double next = x - value / g.slope(x);
    if (std::abs(next - x) <= 2.0 * kEpsilon * std::abs(x) && next >= lo && next <= hi)
      return x;  // converged to round-off
    if (!(next > lo && next < hi) || (iteration % 3 == 0 && hi - lo > 0.5 * width_checked))
      next = 0.5 * (lo + hi);
    if (iteration % 3 == 0) width_checked = hi - lo;
    if (!(next > lo && next < hi)) return lo;  // the bracket is down to adjacent doubles
    x = next;
    value = g.at(x);
    if (value == 0.0) return x;
    (value > 0.0 ? lo : hi) = x;
  }
  return lo;  // not reached: bisection alone would have closed the bracket
}

}  // namespace

double relax_gap_closing_time(double gap, double gap_speed, double gap_drive, double rate,
                              double horizon) {
  assert(rate >= 0.0 && horizon >= 0.0 && std::isfinite(horizon));
  const Gap g{gap, gap_speed, gap_drive - rate * gap_speed, rate};
  // The cheapest answer first: gap' strays from its start by at most |a0| s (gap'' = a0 e^{-rate
  // s} only decays), so over the horizon the gap falls by at most |gap'| H + |a0| H^2 / 2. A gap
  // wider than that (by a margin far above the round-off of gap(s)) cannot close, and no
  // logarithm or exponential is needed: most faces and walls of a slow, dense bed end here.
  if (gap > (std::abs(gap_speed) + 0.5 * std::abs(g.a0) * horizon) * horizon * (1.0 + 1e-12))
    return kNever;
  // gap' changes sign at most once, at turn = (-v0 / D) log1p(x) / x with x = -rate v0 / D,
  // where v0 = gap_speed and D = gap_drive have opposite signs (v(s) -> D / rate, or v0 + D s).
  double turn = kNever;
  if (gap_speed * gap_drive < 0.0) {
    const double x = -rate * gap_speed / gap_drive;
    turn = (-gap_speed / gap_drive) * (x > 0.0 ? std::log1p(x) / x : 1.0);
  }
  const bool closing = gap_speed < 0.0 || (gap_speed == 0.0 && g.a0 < 0.0);
  if (closing) {
    if (gap <= 0.0) return 0.0;
    // Decreasing until the turn (a minimum), then opening.
    const double end = std::min(turn, horizon);
    if (g.at(end) > 0.0) return kNever;
    return closing_root(g, 0.0, end);
  }
  if (gap_speed == 0.0 && g.a0 == 0.0) return kNever;  // at rest and no force
  // Opening until the turn (a maximum), then closing.
  if (!(turn < horizon)) return kNever;
  if (g.at(turn) <= 0.0) return turn;  // started within contact and turned back before leaving
  if (g.at(horizon) > 0.0) return kNever;
  return closing_root(g, turn, horizon);
}

RelaxContactSearch relax_pair_contact_search(const Vec3& dr, const Vec3& va, const RelaxFlight& fa,
                                             const Vec3& vb, const RelaxFlight& fb, double contact,
                                             double horizon) {
  assert(contact > 0.0 && fa.rate >= 0.0 && fb.rate >= 0.0);
  if (dr.squaredNorm() == 0.0) return {0.0, 0};  // concentric: overlapping, no normal
  const Vec3 end_velocity_a = fa.velocity(va, horizon), end_velocity_b = fb.velocity(vb, horizon);
  const Vec3 end_acceleration_a = fa.acceleration(end_velocity_a);
  const Vec3 end_acceleration_b = fb.acceleration(end_velocity_b);
  const double dr_size = dr.norm();
  auto probe_at = [&](double s) {
    const FlightPoint a = flight_point(fa, va, s), b = flight_point(fb, vb, s);
    const Vec3 separation = dr + (a.displacement - b.displacement);
    const double distance = separation.norm();
    const Vec3 n = separation / distance;
    const Vec3 u = a.velocity - b.velocity;
    const Vec3 acceleration_a = fa.acceleration(a.velocity);
    const Vec3 acceleration_b = fb.acceleration(b.velocity);
    const double K =
        relative_acceleration_bound(acceleration_a, end_acceleration_a, fa.rate, acceleration_b,
                                    end_acceleration_b, fb.rate, horizon - s);
    // d/dt (n.a_rel) = n'.a_rel + n.a_rel', |n'| = |u_perp| / |dr| <= V / contact before the
    // contact (0.999: the tolerance may let |dr| dip just below it), |a'| = rate |a|.
    const double V = corner_bound(a.velocity, end_velocity_a, b.velocity, end_velocity_b);
    const double drift = V * K / (0.999 * contact) + fa.rate * acceleration_a.norm() +
                         fb.rate * acceleration_b.norm();
    const double round_off =
        4.0 * kEpsilon * (dr_size + a.displacement.norm() + b.displacement.norm());
    return Probe{distance - contact,
                 n.dot(u),
                 K,
                 n.dot(acceleration_a - acceleration_b),
                 drift,
                 kTouchingTolerance * contact + round_off};
  };
  return earliest_contact(probe_at, horizon);
}

bool relax_pair_separating(const Vec3& dr, const Vec3& va, const RelaxFlight& fa, const Vec3& vb,
                           const RelaxFlight& fb, double horizon) {
  const Vec3 u = va - vb;
  // |dr| G'(0), less a bound far above the round-off of either dot product (its terms may
  // cancel): what the search's n . u can be no smaller than, times |dr|.
  const double approach = dr.dot(u) - 1e-12 * (dr.cwiseAbs().sum() * u.cwiseAbs().sum());
  if (!(approach > 0.0)) return false;
  // The search's K at its first step is at most relative_acceleration_bound's difference form,
  // |a_a - a_b| + min(1, |k_a - k_b| H) min(|a_a|, |a_b|); each length here a sum of
  // magnitudes (never below the length), with a relative margin for their round-off.
  const Vec3 acceleration_a = fa.acceleration(va), acceleration_b = fb.acceleration(vb);
  const double mismatch = std::min(1.0, std::abs(fa.rate - fb.rate) * horizon);
  const double curvature =
      ((acceleration_a - acceleration_b).cwiseAbs().sum() +
       mismatch * std::min(acceleration_a.cwiseAbs().sum(), acceleration_b.cwiseAbs().sum())) *
      (1.0 + 1e-9);
  // G' > K H / 2 (then the first step, at least 2 G' / K, passes the horizon), squared.
  const double turn = 0.5 * curvature * horizon;
  return approach * approach > turn * turn * dr.squaredNorm() * (1.0 + 1e-9);
}

double relax_pair_contact_time(const Vec3& dr, const Vec3& va, const RelaxFlight& fa,
                               const Vec3& vb, const RelaxFlight& fb, double contact,
                               double horizon) {
  return relax_pair_contact_search(dr, va, fa, vb, fb, contact, horizon).time;
}

RelaxContactSearch relax_cylinder_contact_search(const Vec3& offset, const Vec3& v,
                                                 const RelaxFlight& f, double reach,
                                                 double horizon) {
  assert(reach > 0.0 && f.rate >= 0.0);
  using Vec2 = Eigen::Vector2d;
  const Vec2 offset_h = offset.head<2>();
  const double end_speed = f.velocity(v, horizon).head<2>().norm();
  const double offset_size = offset_h.norm();
  auto probe_at = [&](double s) {
    const FlightPoint p = flight_point(f, v, s);
    const Vec2 rho = offset_h + p.displacement.head<2>();
    const Vec2 u = p.velocity.head<2>();
    const double radial = rho.norm();
    const double V = std::max(u.norm(), end_speed);
    const Vec2 a = f.acceleration(p.velocity).head<2>();
    const double A = a.norm();  // the acceleration only decays
    const double round_off = 4.0 * kEpsilon * (offset_size + p.displacement.head<2>().norm());
    // G'' = -(|u|^2 + rho.a) / reach; its rate of change -(3 u.a - rate rho.a) / reach.
    // 1.001: the tolerance may let |rho| pass reach by a hair.
    const double K = (V * V + 1.001 * reach * A) / reach;
    const double drift = A * (3.0 * V + 1.001 * f.rate * reach) / reach;
    return Probe{(reach - radial) * (reach + radial) / (2.0 * reach),
                 -rho.dot(u) / reach,
                 K,
                 -(u.squaredNorm() + rho.dot(a)) / reach,
                 drift,
                 kTouchingTolerance * reach + round_off};
  };
  return earliest_contact(probe_at, horizon);
}

double relax_cylinder_contact_time(const Vec3& offset, const Vec3& v, const RelaxFlight& f,
                                   double reach, double horizon) {
  return relax_cylinder_contact_search(offset, v, f, reach, horizon).time;
}

std::uint64_t relax_contact_cap_hits() {
  return contact_search::cap_hits.load(std::memory_order_relaxed);
}

}  // namespace carom
