#pragma once
/// The brute-force oracle of contact searches (tests/test_relax_roots.cpp, test_cone_contact.cpp):
/// a scan of the gap function G(s) on a fine grid. A contact is the first grid cell where G goes
/// from > 0 to <= 0, refined by bisection; a dip shorter than a cell is caught where G' goes
/// from < 0 to > 0 inside a cell (its minimum, found by bisection on G', is checked).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/vec3.hpp"

namespace carom::test {

/// G and G' at one time.
struct Sample {
  double value, slope;
};
/// G(s) with G'(s).
using GapFunction = std::function<Sample(double)>;

// Earliest s in (0, end] where G (G(0) > 0) reaches zero, scanning `cells` grid cells.
inline double brute_force_contact(const GapFunction& G, double end, int cells) {
  auto bisect = [&](double lo, double hi, auto&& below) {
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (below(mid) ? hi : lo) = mid;
    }
    return hi;
  };
  auto closed = [&](double s) { return G(s).value <= 0.0; };
  Sample previous = G(0.0);
  double s_previous = 0.0;
  for (int i = 1; i <= cells; ++i) {
    const double s = end * i / cells;
    const Sample here = G(s);
    if (here.value <= 0.0) return bisect(s_previous, s, closed);
    if (previous.slope < 0.0 && here.slope > 0.0) {  // a minimum inside the cell: deep enough?
      const double m = bisect(s_previous, s, [&](double t) { return G(t).slope > 0.0; });
      if (G(m).value <= 0.0) return bisect(s_previous, m, closed);
    }
    previous = here;
    s_previous = s;
  }
  return kNever;
}

/// Tally of a family of compared cases.
struct Agreement {
  int cases = 0, hits = 0, misses = 0;
  double worst_error = 0.0;  // |s - s_brute| / tolerance
};

// Compares a predicted time with the oracle; `tolerance(s_brute)` in s. Also: no overlap
// beyond 1e-12 of `length` at the predicted time, and the objects approach there.
inline void compare(Agreement& stats, const GapFunction& G, double predicted, double brute,
                    double tolerance, double length, const char* family, int trial) {
  SCOPED_TRACE(::testing::Message() << family << " case " << trial << ": predicted " << predicted
                                    << " s, brute force " << brute << " s");
  ++stats.cases;
  if (brute == kNever) {
    ++stats.misses;
    EXPECT_EQ(predicted, kNever) << "spurious contact";
    return;
  }
  ++stats.hits;
  ASSERT_NE(predicted, kNever) << "missed contact";
  const double error = std::abs(predicted - brute);
  stats.worst_error = std::max(stats.worst_error, error / tolerance);
  EXPECT_LE(error, tolerance);
  const Sample at = G(predicted);
  EXPECT_GE(at.value, -1e-12 * length) << "overlap at the predicted time";
  EXPECT_LE(at.slope, 0.0) << "not approaching at the predicted time";
}

}  // namespace carom::test
