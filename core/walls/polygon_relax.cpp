// The polygon wall's relax contact: conservative advancement (core/contact_search.hpp) on the
// distance to the plate, G = D(r(s)) - a.
//
// The plate is a convex set, so its distance D is a convex function of the centre, once
// differentiable off the plate with the unit normal n as its gradient and a Hessian H >= 0
// bounded by 1 / D (zero over the face, the curvature of a cylinder about an edge's line or of
// a sphere about a vertex). Along a flight with velocity u and acceleration a_c:
//   G' = n.u,   G'' = u.H.u + n.a_c >= n.a_c >= -|a_c|.
// The acceleration only decays (a_c(t) = a_c(s) e^{-rate (t - s)}), so K = |a_c(s)| bounds
// -G'' over [s, horizon]; and c = n.a_c(s) bounds G''(s) from below, while n.a_c can fall no
// faster than J = |n'| |a_c| + |a_c'| <= V A / D + rate A (V: the largest speed over the rest of
// the horizon, at an end of the segment [v(s), v(H)] the velocity stays on; D >= 0.999 a before
// the contact, the tolerance letting it dip only a hair below a). These are the pair search's
// bounds (relax_roots.cpp) with the plate in the place of the other sphere.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/contact_search.hpp"
#include "core/walls/polygon.hpp"

namespace carom {

RelaxContactSearch PolygonWall::relax_contact_search(const Vec3& r, const Vec3& v, double a,
                                                     const RelaxFlight& f, double horizon) const {
  using contact_search::kEpsilon;
  using contact_search::kTouchingTolerance;
  using contact_search::Probe;
  assert(a > 0.0 && f.rate >= 0.0);
  const double end_speed = f.velocity(v, horizon).norm();
  const double length = (r - centre_).norm() + size_ + a;
  auto probe_at = [&](double s) {
    const contact_search::FlightPoint p = contact_search::flight_point(f, v, s);
    const Vec3 position = r + p.displacement;
    const Closest c = closest(position);
    const double round_off = 4.0 * kEpsilon * (length + p.displacement.norm());
    const double tolerance = kTouchingTolerance * a + round_off;
    if (!(c.distance > 0.0)) return Probe{-a, -1.0, 0.0, 0.0, 0.0, tolerance};  // in the plate
    const Vec3 n = c.feature >= 0 ? Vec3((position - c.point).normalized())
                   : (position - centre_).dot(normal_) >= 0.0 ? normal_
                                                              : Vec3(-normal_);
    const Vec3 acceleration = f.acceleration(p.velocity);
    const double A = acceleration.norm();
    const double V = std::max(p.velocity.norm(), end_speed);
    return Probe{
        c.distance - a, n.dot(p.velocity), A, n.dot(acceleration), V * A / (0.999 * a) + f.rate * A,
        tolerance};
  };
  return contact_search::earliest_contact(probe_at, horizon);
}

}  // namespace carom
