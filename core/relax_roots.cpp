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

namespace carom {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
/// Distance below contact, relative to the contact distance, at which objects count as touching.
constexpr double kTouchingTolerance = 1e-13;

std::atomic<std::uint64_t> cap_hits{0};

/// Displacement and velocity after a flight of s seconds, with one exponential for both
/// (the same expressions as RelaxFlight::displacement and ::velocity).
struct FlightPoint {
  Vec3 displacement;
  Vec3 velocity;
};

FlightPoint flight_point(const RelaxFlight& f, const Vec3& v0, double s) {
  const double x = f.rate * s;
  double phi1, phi2;
  if (x < 1e-3) {
    phi1 = relax_phi1(x);
    phi2 = relax_phi2(x);
  } else {
    const double e = std::expm1(-x);
    phi1 = -e / x;
    phi2 = (x + e) / (x * x);
  }
  const Vec3 a0 = f.acceleration(v0);
  return {s * v0 + (s * s * phi2) * a0, v0 + (s * phi1) * a0};
}

/// The gap function of a conservative-advancement search at one time s, with a lower bound on
/// its second derivative over [s, horizon]: G''(s + tau) >= max(-K, c - J tau).
struct Probe {
  double gap;              ///< G(s), zero at contact, positive before
  double slope;            ///< G'(s)
  double curvature_bound;  ///< K >= -G''(t) for every t in [s, horizon]
  double curvature_now;    ///< c <= G''(s) (-K where nothing better is known)
  double curvature_drift;  ///< J >= 0: how fast that lower bound may fall, per second
  double tolerance;        ///< G below which the objects count as touching
};

/// First positive root of gap + slope h - k h^2 / 2 (gap >= 0, k >= 0), kNever if none; in
/// forms without cancellation.
double quadratic_step(double gap, double slope, double k) {
  if (slope < 0.0) return 2.0 * gap / (std::sqrt(slope * slope + 2.0 * k * gap) - slope);
  if (!(k > 0.0)) return kNever;
  return (slope + std::sqrt(slope * slope + 2.0 * k * gap)) / k;
}

/// The longest step h (up to past `remaining`, the time left to the horizon) over which
/// gap + slope tau + (lower bound of G'') tau^2 / 2 stays positive. With the plain bound K this
/// is quadratic_step(K). Using G'' >= c - J tau as well, the curvature to allow over a step h is
/// k(h) = clamp(J h - c, 0, K); h is safe when h <= phi(h) = quadratic_step(k(h)). phi falls
/// as h grows, so the safe steps are an interval [0, h*]: bisect for h*, from the safe
/// quadratic_step(K) to phi of it (which is >= h*).
double safe_step(const Probe& p, double gap, double remaining) {
  const double K = p.curvature_bound, c = p.curvature_now, J = p.curvature_drift;
  const double plain = quadratic_step(gap, p.slope, K);
  if (!(c > -K) || plain >= remaining) return plain;
  auto phi = [&](double h) { return quadratic_step(gap, p.slope, std::clamp(J * h - c, 0.0, K)); };
  if (remaining < phi(remaining)) return kNever;  // safe to the horizon
  double safe = plain, unsafe = std::min(phi(plain), remaining);
  for (int i = 0; i < 8 && unsafe > 1.05 * safe; ++i) {
    const double mid = std::sqrt(safe * unsafe);
    (mid <= phi(mid) ? safe : unsafe) = mid;
  }
  return safe;
}

/// Newton polish of a contact found at s (G <= tolerance, G' < 0), kept only where it improves
/// |G| without overlapping beyond the tolerance and stays within [earliest, horizon].
template <class ProbeAt>
double polish(const ProbeAt& probe_at, double s, const Probe& p, double earliest, double horizon) {
  const double s_new = std::clamp(s + p.gap / -p.slope, earliest, horizon);
  if (s_new == s) return s;
  const Probe q = probe_at(s_new);
  return (q.gap >= -q.tolerance && std::abs(q.gap) < std::abs(p.gap)) ? s_new : s;
}

/// Conservative advancement from s = 0 to the first contact (G <= tolerance while G' < 0).
/// Approaching, the step is taken on G itself; otherwise on max(G, 0) + tolerance, which lets
/// a touch at rest (G = G' = 0) move on, at the price of missing dips shallower than the
/// tolerance.
template <class ProbeAt>
RelaxContactSearch earliest_contact(const ProbeAt& probe_at, double horizon) {
  assert(horizon >= 0.0 && std::isfinite(horizon));
  double s = 0.0, s_safe = 0.0;  // s_safe: the previous iterate, before which no contact is
  for (int iteration = 1; iteration <= kRelaxContactMaxIterations; ++iteration) {
    const Probe p = probe_at(s);
    if (p.gap <= p.tolerance && p.slope < 0.0)
      return {polish(probe_at, s, p, s_safe, horizon), iteration};
    const double gap = p.slope < 0.0 ? p.gap : std::max(p.gap, 0.0) + p.tolerance;
    double next = s + safe_step(p, gap, horizon - s);
    if (!(next <= horizon)) return {kNever, iteration};
    if (next == s) {
      if (p.slope < 0.0) return {s, iteration};  // the contact is within an ulp of s
      next = std::nextafter(s, horizon);
    }
    s_safe = s;
    s = next;
  }
  cap_hits.fetch_add(1, std::memory_order_relaxed);
  return {s, kRelaxContactMaxIterations};
}

/// Largest of |x - y| over x in {x0, x1} and y in {y0, y1}: a bound on |x(t) - y(t)| while
/// x(t) and y(t) stay on the segments [x0, x1] and [y0, y1].
double corner_bound(const Vec3& x0, const Vec3& x1, const Vec3& y0, const Vec3& y1) {
  return std::sqrt(std::max({(x0 - y0).squaredNorm(), (x0 - y1).squaredNorm(),
                             (x1 - y0).squaredNorm(), (x1 - y1).squaredNorm()}));
}

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
  return cap_hits.load(std::memory_order_relaxed);
}

}  // namespace carom
