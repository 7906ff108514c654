#pragma once
/// Conservative advancement to the earliest contact of a gap function G(s) (zero at contact,
/// positive before) along a relax flight, shared by the relax contact searches (pairs and the
/// cylinder in relax_roots.cpp, the cone in walls/cone_relax.cpp). The method and its
/// guarantee are described at the top of relax_roots.cpp: with a lower bound G'' >= -K valid
/// from the current time to the horizon, a step to the first root of the lower bound
/// G + G' h - K h^2 / 2 can never pass a contact.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "relax_roots.hpp"

namespace carom::contact_search {

/// Counts one search that stopped at kRelaxContactMaxIterations (relax_contact_cap_hits).
void count_cap_hit();

/// Machine epsilon of double (relative round-off of one operation).
inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
/// Distance below contact, relative to the contact distance, at which objects count as touching.
inline constexpr double kTouchingTolerance = 1e-13;

/// Displacement and velocity after a flight of s seconds, with one exponential for both
/// (the same expressions as RelaxFlight::displacement and ::velocity).
struct FlightPoint {
  Vec3 displacement;
  Vec3 velocity;
};

inline FlightPoint flight_point(const RelaxFlight& f, const Vec3& v0, double s) {
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
inline double quadratic_step(double gap, double slope, double k) {
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
inline double safe_step(const Probe& p, double gap, double remaining) {
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
  count_cap_hit();
  return {s, kRelaxContactMaxIterations};
}

/// Largest of |x - y| over x in {x0, x1} and y in {y0, y1}: a bound on |x(t) - y(t)| while
/// x(t) and y(t) stay on the segments [x0, x1] and [y0, y1].
inline double corner_bound(const Vec3& x0, const Vec3& x1, const Vec3& y0, const Vec3& y1) {
  return std::sqrt(std::max({(x0 - y0).squaredNorm(), (x0 - y1).squaredNorm(),
                             (x1 - y0).squaredNorm(), (x1 - y1).squaredNorm()}));
}

}  // namespace carom::contact_search
