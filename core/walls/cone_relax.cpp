// The cone wall's relax contact: conservative advancement (core/contact_search.hpp), as for
// the cylinder in relax_roots.cpp, which is the cone's special case slope = 0.
//
// Gap function at a probe time s, with rho the horizontal offset from the axis, u, a the
// velocity and acceleration, L(z) the locus radius (walls/cone.hpp) and k the slope:
//   G = (L^2 - |rho|^2) / (2 L_s),   L_s = L at the probe (a positive constant for the step),
// equal to L - |rho| (the locus gap) near the wall and smooth on the axis. With L' = k u_z and
// L'' = k a_z:
//   G'  = (L L' - rho.u_h) / L_s,
//   G'' = (L'^2 + L L'' - |u_h|^2 - rho.a_h) / L_s.
// Lower bound over [s, horizon], while inside (|rho| <= L; the search stops at the first
// contact): -L_s G'' <= V_h^2 + L_max (A_h + |k| A_z), where V_h, V_z bound the horizontal and
// vertical speeds (the velocity stays on the segment [v(s), v(H)]), A_h, A_z are the
// acceleration's parts now (it only decays, a(t) = a(s) e^{-rate (t - s)}) and
// L_max = L_s + |k| V_z (H - s) bounds L. Its rate of change,
//   d(L_s G'')/dt = 3 k^2 u_z a_z - rate k L a_z - 3 u_h.a_h + rate rho.a_h,
// is bounded by J L_s = 3 (k^2 V_z A_z + V_h A_h) + rate L_max (|k| A_z + A_h).
// For k = 0 these are the cylinder's G, K and J term for term.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/contact_search.hpp"
#include "core/walls/cone.hpp"

namespace carom {

RelaxContactSearch ConeWall::relax_contact_search(const Vec3& r, const Vec3& v, double a,
                                                  const RelaxFlight& f, double horizon) const {
  using contact_search::kEpsilon;
  using contact_search::kTouchingTolerance;
  using contact_search::Probe;
  using Vec2 = Eigen::Vector2d;
  assert(a >= 0.0 && f.rate >= 0.0);
  // A centre at or beyond the apex's height (no locus there) is outside: touching now.
  if (!(locus_at(r.z(), a) > 0.0)) return {0.0, 0};
  const Vec2 offset_h(r.x() - axis_x_, r.y() - axis_y_);
  const Vec3 end_velocity = f.velocity(v, horizon);
  const double end_speed_h = end_velocity.head<2>().norm();
  const double end_speed_z = std::abs(end_velocity.z());
  const double k = std::abs(slope_);
  // Lengths whose round-off enters G: the offset, the locus' terms.
  const double length = offset_h.norm() + radius_bottom_ + k * std::abs(r.z() - z_bottom_) +
                        k * std::abs(r.z()) + a * secant_;
  auto probe_at = [&](double s) {
    const contact_search::FlightPoint p = contact_search::flight_point(f, v, s);
    const Vec2 rho = offset_h + p.displacement.head<2>();
    const double radial = rho.norm();
    const double L = locus_at(r.z() + p.displacement.z(), a);
    const double round_off = 4.0 * kEpsilon * (length + (1.0 + k) * p.displacement.norm());
    const double tolerance = kTouchingTolerance * std::max(L, 0.0) + round_off;
    if (!(L > 0.0)) return Probe{L - radial, -1.0, 0.0, 0.0, 0.0, tolerance};  // past the apex
    const Vec2 u = p.velocity.head<2>();
    const Vec3 acceleration = f.acceleration(p.velocity);
    const Vec2 a_h = acceleration.head<2>();
    const double L1 = slope_ * p.velocity.z(), L2 = slope_ * acceleration.z();
    const double V_h = std::max(u.norm(), end_speed_h);
    const double V_z = std::max(std::abs(p.velocity.z()), end_speed_z);
    const double A_h = a_h.norm(), A_z = std::abs(acceleration.z());
    // 1.001: the tolerance may let |rho| pass L by a hair.
    const double L_max = 1.001 * (L + k * V_z * (horizon - s));
    const double K = (V_h * V_h + L_max * (A_h + k * A_z)) / L;
    const double drift =
        (3.0 * (k * k * V_z * A_z + V_h * A_h) + f.rate * L_max * (k * A_z + A_h)) / L;
    return Probe{(L - radial) * (L + radial) / (2.0 * L),
                 (L * L1 - rho.dot(u)) / L,
                 K,
                 (L1 * L1 + L * L2 - u.squaredNorm() - rho.dot(a_h)) / L,
                 drift,
                 tolerance};
  };
  return contact_search::earliest_contact(probe_at, horizon);
}

}  // namespace carom
