#include "polynomial_roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace carom {

double root_bound(const Quartic& p) {
  const int n = p.degree();
  if (n < 0) return std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (int k = 1; k <= n; ++k) {
    const double ratio = std::abs(p.c[n - k] / p.c[n]) * (k == n ? 0.5 : 1.0);
    const double root = k == 1   ? ratio
                        : k == 2 ? std::sqrt(ratio)
                        : k == 3 ? std::cbrt(ratio)
                                 : std::sqrt(std::sqrt(ratio));
    largest = std::max(largest, root);
  }
  return 2.0 * largest;
}

int real_roots(const Quartic& p, double lo, double hi, std::array<double, 4>& roots,
               double tolerance) {
  const int n = p.degree();
  if (n <= 0) return 0;
  if (n == 1) {
    const double root = -p.c[0] / p.c[1];
    if (!(root > lo && root < hi)) return 0;
    roots[0] = root;
    return 1;
  }
  if (n == 2) {
    // Closed form without cancellation: q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, roots q / a and
    // c / q. A double root shows as none when round-off makes the discriminant negative.
    const double a = p.c[2], b = p.c[1], c = p.c[0];
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
    if (r1 < r0) std::swap(r0, r1);
    int count = 0;
    for (double root : {r0, r1})
      if (root > lo && root < hi && (count == 0 || root > roots[0])) roots[count++] = root;
    return count;
  }
  // The extrema of p cut (lo, hi) into pieces on which p is monotone.
  std::array<double, 4> turns{};
  const int m = real_roots(p.derivative(), lo, hi, turns, tolerance);
  int count = 0;
  double a = lo, value_a = p(lo);
  for (int k = 0; k <= m; ++k) {
    const double b = k < m ? turns[k] : hi;
    const double value_b = p(b);
    if (value_a == 0.0 && a > lo) {
      roots[count++] = a;  // exactly zero at an extremum
    } else if (value_a != 0.0 && value_b != 0.0 && (value_a < 0.0) != (value_b < 0.0)) {
      roots[count++] = bracketed_root(
          [&](double s) {
            return std::pair{p(s), p.slope(s)};
          },
          a, b, value_a, value_b, -1.0, tolerance);
    }
    a = b;
    value_a = value_b;
  }
  return count;
}

}  // namespace carom
