// The cone wall: geometry, checks, and the ballistic contact time.
//
// Ballistic contact. With d the horizontal offset of the centre from the axis, u the
// horizontal velocity and gravity along z, d(s) = d + u s and the locus radius at the centre's
// height is q(s) = L + k v_z s + (k g_z / 2) s^2 (L = locus now, k = slope). The contact
// condition F(s) = |d(s)|^2 - q(s)^2 = 0 is a quartic (a quadratic without gravity or for a
// cylinder-like cone). F = (rho - q)(rho + q): on the cone's nappe (q > 0) F < 0 inside and
// F > 0 outside, so a contact is a root where F rises through zero with q > 0; a root with
// q < 0 is the other nappe (beyond the apex of the locus), not a contact. Inside means
// rho < q, so q cannot reach zero before a contact: the search ends at the first zero of q,
// which keeps it on the right nappe. The roots of F' (a cubic, found through its own
// derivative's roots) cut [0, S] (S: Fujiwara's bound, no root beyond, or q's zero) into pieces
// on which F is monotone; they are scanned in time order and the first rising piece that
// crosses zero holds the contact. It is bracketed there and polished on the locus gap
// G = q - rho itself, which round-off affects far less than F near the apex of the locus (F is
// known to round-off of the squared lengths, a gap error of eps L^2 / (2 rho) there). F(0) is
// formed as (rho - L)(rho + L), without the cancellation of rho^2 - L^2 near contact.
#include "core/walls/cone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/polynomial_roots.hpp"
#include "core/roots.hpp"

namespace carom {

ConeWall::ConeWall(double axis_x, double axis_y, double z_bottom, double radius_bottom,
                   double z_top, double radius_top)
    : axis_x_(axis_x),
      axis_y_(axis_y),
      z_bottom_(z_bottom),
      radius_bottom_(radius_bottom),
      z_top_(z_top),
      radius_top_(radius_top) {
  if (!std::isfinite(axis_x) || !std::isfinite(axis_y) || !std::isfinite(z_bottom) ||
      !std::isfinite(radius_bottom) || !std::isfinite(z_top) || !std::isfinite(radius_top))
    throw std::invalid_argument("a cone's axis, heights and radii must be finite");
  if (!(z_top > z_bottom)) throw std::invalid_argument("a cone needs z_top > z_bottom");
  if (radius_bottom < 0.0 || radius_top < 0.0 || !(std::max(radius_bottom, radius_top) > 0.0))
    throw std::invalid_argument("a cone's radii must be >= 0, and one of them > 0");
  slope_ = (radius_top - radius_bottom) / (z_top - z_bottom);
  secant_ = std::sqrt(1.0 + slope_ * slope_);
  cosine_ = 1.0 / secant_;
}

double ConeWall::apex_z() const {
  if (slope_ == 0.0) return std::numeric_limits<double>::infinity();
  return z_bottom_ - radius_bottom_ / slope_;
}

double ConeWall::gap(const Vec3& r, double a) const {
  const double dx = r.x() - axis_x_, dy = r.y() - axis_y_;
  return (radius_at(r.z()) - std::sqrt(dx * dx + dy * dy)) * cosine_ - a;
}

Vec3 ConeWall::contact_normal(const Vec3& r) const {
  const double dx = r.x() - axis_x_, dy = r.y() - axis_y_;
  const double rho = std::sqrt(dx * dx + dy * dy);
  if (!(rho > 0.0)) return Vec3(0.0, 0.0, slope_ >= 0.0 ? 1.0 : -1.0);  // at the apex only
  return Vec3(-dx / rho * cosine_, -dy / rho * cosine_, slope_ * cosine_);
}

double ConeWall::ballistic_contact_time(const Vec3& r, const Vec3& v, double a,
                                        const Vec3& g) const {
  const double dx = r.x() - axis_x_, dy = r.y() - axis_y_;
  const double rho = std::sqrt(dx * dx + dy * dy);
  const double locus = locus_at(r.z(), a);
  if (!(locus > 0.0)) return 0.0;  // beyond the locus' apex: overlapping, touching now
  const double q1 = slope_ * v.z(), q2 = 0.5 * slope_ * g.z();  // q(s) = locus + q1 s + q2 s^2
  const Quartic F{{(rho - locus) * (rho + locus), 2.0 * (dx * v.x() + dy * v.y() - locus * q1),
                   v.x() * v.x() + v.y() * v.y() - q1 * q1 - 2.0 * locus * q2, -2.0 * q1 * q2,
                   -q2 * q2}};
  if (F.degree() <= 0) return kNever;  // no relative motion: as at rest
  // G = q - rho, the locus gap (m), with G': the polished roots are those of G, which is known
  // to round-off of the lengths (F only to round-off of their squares).
  auto locus_gap = [&](double s) {
    const double x = dx + v.x() * s, y = dy + v.y() * s;
    const double radial = std::sqrt(x * x + y * y);
    const double radial_speed = radial > 0.0 ? (x * v.x() + y * v.y()) / radial : 0.0;
    // -G, rising through zero at contact.
    return std::pair{radial - (locus + s * (q1 + s * q2)), radial_speed - (q1 + 2.0 * q2 * s)};
  };
  auto contact_in = [&](double lo, double hi) {
    const double before = locus_gap(lo).first, after = locus_gap(hi).first;
    if (!(before < 0.0)) return lo;
    if (!(after > 0.0)) return hi;
    // Newton on G starts from the root of F (to 1e-9) where F brackets one.
    const double guess = F(lo) < 0.0 && F(hi) > 0.0 ? monotone_root(F, lo, hi, 1e-9) : -1.0;
    return bracketed_root(locus_gap, lo, hi, before, after, guess);
  };
  // The locus radius q reaches zero (the apex of the locus) at `apex`: inside means
  // rho < q, so the contact comes no later, while q > 0 (this nappe) throughout.
  const double apex = first_upward_crossing(-q2, -q1, -locus);
  const double end = std::min({root_bound(F), apex, kLongestFlight});
  std::array<double, 4> turns{};
  // The turns to 1e-9 (relative): F's value there is then its extremum's to ~1e-18.
  const int m = real_roots(F.derivative(), 0.0, end, turns, 1e-9);
  double start = 0.0, value_start = F(0.0);
  for (int k = 0; k <= m; ++k) {
    const double stop = k < m ? turns[k] : end;
    const double value_stop = F(stop);
    if (value_stop > value_start) {  // moving out through the locus
      if (value_start >= 0.0) {
        if (k == 0) return 0.0;  // at or past contact and moving outward
      } else if (value_stop >= 0.0) {
        return contact_in(start, stop);
      }
    } else if (k == 0 && k < m && value_start >= 0.0 && value_stop >= 0.0) {
      return stop;  // past contact, moving inward, but turns outward before it is back inside
    }
    start = stop;
    value_start = value_stop;
  }
  // Reaching the locus' apex, it has touched (F lost the root to round-off: a contact within
  // round-off of the apex).
  if (apex <= kLongestFlight && end == apex) return contact_in(start, apex);
  return kNever;
}

void ConeWall::validate(const std::string& name, const Vec3& gravity, const Domain& domain) const {
  if (gravity.x() != 0.0 || gravity.y() != 0.0)
    throw std::invalid_argument("wall '" + name +
                                "': a cone's axis is along z, so gravity must be along z too");
  if (domain.periodic[2])
    throw std::invalid_argument("wall '" + name +
                                "': a cone's radius changes along z, so z must not be periodic");
  if (!(radius_at(domain.lower.z()) > 0.0 && radius_at(domain.upper.z()) > 0.0)) {
    std::ostringstream out;
    out << "wall '" << name << "': the cone's apex (z = " << apex_z()
        << " m) lies within the domain's heights [" << domain.lower.z() << ", " << domain.upper.z()
        << "] m; the surface continues past z_bottom and z_top with the same slope, so its apex "
           "must lie outside the domain";
    throw std::invalid_argument(out.str());
  }
}

std::string ConeWall::description() const {
  std::ostringstream out;
  out << "cone R = " << radius_bottom_ << " m at z = " << z_bottom_ << " m to R = " << radius_top_
      << " m at z = " << z_top_ << " m, axis through (" << axis_x_ << ", " << axis_y_ << ")";
  return out.str();
}

}  // namespace carom
