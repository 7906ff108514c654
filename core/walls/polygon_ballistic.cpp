// The polygon wall's ballistic contact time.
//
// Features. The centre's distance to the plate is the least of its distances to the plate's
// features, each counted only where that feature holds the closest point: the face (where the
// centre's foot is inside the polygon), each edge's line (where the centre projects inside the
// edge) and each vertex. Relative to a feature the centre moves as x(s) = p0 + p1 s + p2 s^2
// in the directions the feature does not extend along (the face: along its normal; an edge:
// across its line; a vertex: all three), so each feature's contact condition
//   F(s) = a^2 - |x(s)|^2 = 0
// is a polynomial of degree 4 (2 without gravity); F > 0 while the sphere overlaps the
// feature's plane, line or point, and a contact is a root where F rises through zero.
//
// The first contact is the earliest root, over all features, at which that feature holds the
// closest point (to 1e-12 of the lengths involved: its distance equals the plate's, as
// closest() finds it). Proof that none is missed: at the first contact s* the closest point
// lies in the interior of one feature (the face, an edge) or at a vertex; that feature holds
// the closest point on a neighbourhood of s*, where its distance is the plate's, > a before s*
// and = a at s*: a rising root of its F. Roots of a feature where it does not hold the closest
// point (the face's plane beside the polygon, an edge's line beyond its ends) are not
// contacts; nor is a feature that starts holding the closest point while already within a,
// because another feature reached a first.
//
// Each feature's F is scanned as the cone's (walls/cone.cpp): the roots of F' (a cubic) cut
// [0, S] (S: Fujiwara's bound, or an earlier contact already found) into pieces on which F is
// monotone; each piece that rises through zero holds one root, bracketed and polished on the
// distance itself, a - |x(s)|, known to round-off of the lengths (F only to round-off of their
// squares). As for the other shapes, a feature already within a (round-off) at s = 0 gives 0
// if it is approaching and, if moving away, the time it turns back if it does so before it is
// clear, else its next contact.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/polynomial_roots.hpp"
#include "core/walls/polygon.hpp"

namespace carom {

namespace {

/// Two distances (to a feature, to the plate) count as equal within this fraction of the
/// lengths involved: far above their round-off (a few eps), far below any geometric difference
/// that matters (a sphere accepted on a feature 1e-12 of the lengths farther than the plate).
constexpr double kSameDistance = 1e-12;

/// The centre's offset from a feature, x(s) = p0 + p1 s + p2 s^2 (m, m/s, m/s^2).
struct Track {
  Vec3 p0, p1, p2;
  Vec3 at(double s) const { return p0 + s * (p1 + s * p2); }
  Vec3 rate(double s) const { return p1 + 2.0 * s * p2; }
};

/// The part of w across the unit direction t.
Vec3 across(const Vec3& w, const Vec3& t) {
  return w - w.dot(t) * t;
}

/// Earliest s in [0, limit] at which the feature with offset x touches a sphere of radius a
/// and `holds(s)` (the feature holds the closest point then); kNever if none.
template <class Holds>
double feature_contact(const Track& x, double a, double limit, const Holds& holds) {
  const double size0 = x.p0.norm();
  const Quartic F{{(a - size0) * (a + size0), -2.0 * x.p0.dot(x.p1),
                   -(x.p1.squaredNorm() + 2.0 * x.p0.dot(x.p2)), -2.0 * x.p1.dot(x.p2),
                   -x.p2.squaredNorm()}};
  if (F.degree() <= 0) return kNever;  // no relative motion: as at rest
  // a - |x|, rising through zero at contact, with its slope.
  auto overlap = [&](double s) {
    const Vec3 y = x.at(s);
    const double distance = y.norm();
    return std::pair{a - distance, distance > 0.0 ? -y.dot(x.rate(s)) / distance : 0.0};
  };
  auto contact_in = [&](double lo, double hi) {
    const double before = overlap(lo).first, after = overlap(hi).first;
    if (!(before < 0.0)) return lo;
    if (!(after > 0.0)) return hi;
    const double guess = F(lo) < 0.0 && F(hi) > 0.0 ? monotone_root(F, lo, hi, 1e-9) : -1.0;
    return bracketed_root(overlap, lo, hi, before, after, guess);
  };
  const double end = std::min({root_bound(F), kLongestFlight, limit});
  std::array<double, 4> turns{};
  const int m = end > 0.0 ? real_roots(F.derivative(), 0.0, end, turns, 1e-9) : 0;
  double start = 0.0, value_start = F(0.0);
  for (int k = 0; k <= m; ++k) {
    const double stop = k < m ? turns[k] : end;
    const double value_stop = F(stop);
    if (value_stop > value_start) {  // closing in on the feature
      if (value_start >= 0.0) {
        if (k == 0 && holds(0.0)) return 0.0;  // within a and approaching
      } else if (value_stop >= 0.0) {
        const double s = contact_in(start, stop);
        if (holds(s)) return s;
      }
    } else if (k == 0 && k < m && value_start >= 0.0 && value_stop >= 0.0 && holds(stop)) {
      return stop;  // within a, moving away, but turns back before it is clear
    }
    start = stop;
    value_start = value_stop;
  }
  return kNever;
}

}  // namespace

double PolygonWall::ballistic_contact_time(const Vec3& r, const Vec3& v, double a,
                                           const Vec3& g) const {
  const Vec3 half_g = 0.5 * g;
  const double lengths = a + size_ + (r - centre_).norm();
  const double speed = v.norm(), pull = half_g.norm();
  // Whether the feature at offset x holds the closest point at s: its distance is the plate's.
  auto holds_for = [&](const Track& x) {
    return [&, x](double s) {
      const Closest c = closest(r + s * (v + s * half_g));
      const double tolerance = kSameDistance * (lengths + s * (speed + s * pull));
      return std::abs(x.at(s).norm() - c.distance) <= tolerance;
    };
  };
  // Every feature lies in the plane, so nothing is touched while the centre stays more than a
  // from it: side * h(s) = |h0| + p1 s + p2 s^2 (side: +-1, the side now). Where that has a
  // lowest value for s >= 0 (p2 > 0, or p2 = 0 moving away) above a by more than round-off,
  // no contact.
  const double h0 = (r - centre_).dot(normal_);
  const double side = h0 >= 0.0 ? 1.0 : -1.0;
  const double p1 = side * v.dot(normal_), p2 = side * half_g.dot(normal_);
  if (p2 > 0.0 || (p2 == 0.0 && p1 >= 0.0)) {
    const double lowest_at = p2 > 0.0 ? std::max(0.0, -p1 / (2.0 * p2)) : 0.0;
    const double lowest = std::abs(h0) + lowest_at * (p1 + lowest_at * p2);
    const double round_off =
        kSameDistance * (lengths + lowest_at * (std::abs(p1) + lowest_at * p2));
    if (lowest - a > round_off) return kNever;
  }
  // Nor while the centre stays outside the ball about the plate's centre that holds the plate
  // with a margin a (and 1e-9 of it for round-off): one quartic instead of 2n + 1.
  const double reach = (size_ + a) * (1.0 + 1e-9);
  if ((r - centre_).norm() > reach && feature_contact(Track{r - centre_, v, half_g}, reach, kNever,
                                                      [](double) { return true; }) == kNever)
    return kNever;
  double best = kNever;
  auto consider = [&](const Track& x) {
    if (best == 0.0) return;
    best = std::min(best, feature_contact(x, a, best, holds_for(x)));
  };
  // The face: along the normal.
  const Vec3& n = normal_;
  consider(Track{(r - centre_).dot(n) * n, v.dot(n) * n, half_g.dot(n) * n});
  for (const Edge& e : edges_) {
    const Vec3& t = e.direction;
    consider(Track{across(r - e.start, t), across(v, t), across(half_g, t)});  // its line
    consider(Track{r - e.start, v, half_g});                                   // its start
  }
  return best;
}

}  // namespace carom
