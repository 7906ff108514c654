#pragma once
/// Real roots of polynomials of degree at most four (the contact conditions of ballistic flights
/// against curved walls), isolated without a closed form: the roots of the derivative split an
/// interval into pieces on which the polynomial is monotone, and each piece that changes sign
/// holds exactly one root, bracketed and polished to round-off (safeguarded Newton).
#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace carom {

/// p(s) = c[0] + c[1] s + ... + c[4] s^4 (c[k] in the unit of p per s^k).
struct Quartic {
  std::array<double, 5> c{};  ///< Coefficients, lowest degree first.

  /// Highest k with c[k] != 0; -1 for the zero polynomial.
  int degree() const {
    for (int k = 4; k >= 0; --k)
      if (c[k] != 0.0) return k;
    return -1;
  }
  /// p(s) by Horner's rule.
  double operator()(double s) const {
    return c[0] + s * (c[1] + s * (c[2] + s * (c[3] + s * c[4])));
  }
  /// p'(s).
  double slope(double s) const {
    return c[1] + s * (2.0 * c[2] + s * (3.0 * c[3] + s * 4.0 * c[4]));
  }
  /// The polynomial p'.
  Quartic derivative() const { return Quartic{{c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0}}; }
};

/// Fujiwara's bound: every root z of p (complex too) of degree n has
/// |z| <= 2 max(|c[n-1] / c[n]|, |c[n-2] / c[n]|^(1/2), ..., |c[0] / (2 c[n])|^(1/n)), which
/// follows the polynomial's own time scale. Infinity for the zero polynomial, 0 for a non-zero
/// constant.
double root_bound(const Quartic& p);

/// The wall searches report contacts later than this (s) as never: a quartic is evaluated no
/// further than this along a flight.
inline constexpr double kLongestFlight = 1e12;

/// A root of f in [lo, hi] where f(lo) = value_lo and f(hi) = value_hi are non-zero with
/// opposite signs; `f(x)` returns {f(x), f'(x)}. Safeguarded Newton (as rtsafe) from `guess`
/// if it lies inside (lo, hi) (the root of a nearby function, say), else from the end nearer
/// the root; a bisection instead wherever the Newton step would leave the bracket or does not
/// at least halve the step before it. Stops when a step is below `tolerance` relative to x
/// (2 eps: converged to round-off); at worst returns the bracket end on the side of value_lo's
/// sign, within an ulp of a root. With one sign change in [lo, hi] it is that root.
template <class F>
double bracketed_root(const F& f, double lo, double hi, double value_lo, double value_hi,
                      double guess = -1.0,
                      double tolerance = 2.0 * std::numeric_limits<double>::epsilon()) {
  const bool rising = value_lo < 0.0;  // f < 0 before the root
  double x = guess;
  if (!(guess > lo && guess < hi)) x = std::abs(value_lo) <= std::abs(value_hi) ? lo : hi;
  auto [value, slope] = f(x);
  if (value == 0.0) return x;
  if (x != lo && x != hi) ((value < 0.0) == rising ? lo : hi) = x;
  double step = hi - lo, step_before = step;
  for (int iteration = 1; iteration <= 200; ++iteration) {
    const double newton = slope != 0.0 ? x - value / slope : lo - 1.0;
    double next;
    if (newton > lo && newton < hi && std::abs(newton - x) <= 0.5 * std::abs(step_before)) {
      next = newton;
    } else {
      next = 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) break;  // the bracket is down to adjacent doubles
    }
    step_before = step;
    step = next - x;
    if (std::abs(step) <= tolerance * std::abs(x)) return next;  // converged
    x = next;
    std::tie(value, slope) = f(x);
    if (value == 0.0) return x;
    ((value < 0.0) == rising ? lo : hi) = x;
  }
  return lo;  // the side of value_lo's sign
}

/// The same, evaluating f at the ends.
template <class F>
double bracketed_root(const F& f, double lo, double hi, double guess = -1.0) {
  return bracketed_root(f, lo, hi, f(lo).first, f(hi).first, guess);
}

/// The root of p in [lo, hi] where p(lo) and p(hi) are non-zero with opposite signs and p is
/// monotone (bracketed_root), to `tolerance` relative.
inline double monotone_root(const Quartic& p, double lo, double hi,
                            double tolerance = 2.0 * std::numeric_limits<double>::epsilon()) {
  return bracketed_root(
      [&](double s) {
        return std::pair{p(s), p.slope(s)};
      },
      lo, hi, p(lo), p(hi), -1.0, tolerance);
}

/// The real roots of p in the open interval (lo, hi) (finite bounds), ascending; returns how
/// many (at most 4). Degrees 1 and 2 in closed form; above, through the roots of p'. A root
/// where p only touches zero (even multiplicity) is found when p is exactly zero at the
/// extremum; otherwise a double root shows as two close roots or none, within round-off of p.
/// `tolerance`: the relative precision of the roots above degree 2 (2 eps: round-off).
int real_roots(const Quartic& p, double lo, double hi, std::array<double, 4>& roots,
               double tolerance = 2.0 * std::numeric_limits<double>::epsilon());

}  // namespace carom
