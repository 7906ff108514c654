// The Morsi & Alexander (1972) single-sphere drag (fluid/morsi_alexander.hpp): C_D on each of
// its eight ranges against values computed with Python from C_D = a1 + a2/Re + a3/Re^2 and the
// published table, its Stokes limit, and its K through the closure selector (no porosity in it).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fluid/drag.hpp"
#include "fluid/morsi_alexander.hpp"
#include "tests/assertions.hpp"

namespace carom {
namespace {

using test::close;

// One Re inside each range; Python values, 1e-12 relative (the same three-term sum).
TEST(MorsiAlexander, DragCoefficientOnEveryRange) {
  const double re[] = {0.05, 0.5, 5.0, 50.0, 500.0, 2000.0, 7000.0, 2e4};
  const double cd[] = {480.0,    49.511199999999995,  6.8997839999999995, 1.500032,
                       0.549948, 0.41943499999999995, 0.4017322040816326, 0.44951675};
  for (int k = 0; k < 8; ++k) EXPECT_TRUE(close(morsi_alexander_cd(re[k]), cd[k], 1e-12)) << re[k];
}

// Re -> 0: Stokes drag, C_D Re / 24 = 1 exactly on the first range (also at Re = 0, a particle
// moving with the gas), and C_D Re / 24 agrees with C_D itself on the other ranges.
TEST(MorsiAlexander, StokesLimitAndFactor) {
  EXPECT_EQ(morsi_alexander_factor(0.0), 1.0);
  EXPECT_EQ(morsi_alexander_factor(0.07), 1.0);
  for (double re : {0.3, 3.0, 30.0, 300.0, 3000.0, 8000.0, 3e4})
    EXPECT_TRUE(close(morsi_alexander_factor(re), morsi_alexander_cd(re) * re / 24.0, 1e-14)) << re;
}

// K = F / |u - v| with F = C_D (pi/8) d^2 rho_g |u - v|^2: a 3 mm sphere at 0.7 m/s slip in air
// (Re = 140, C_D = 0.9645...): Python K = 2.746211324963329e-06 kg/s, 1e-12. The porosity does
// not enter: the same K at eps = 0.5.
TEST(MorsiAlexander, ClosureKIsTheSingleSphereDragAtAnyPorosity) {
  DragInput in;
  in.diameter = 3e-3;
  in.slip = 0.7;
  const DragClosure closure(parse_drag_closure("morsi_alexander"));
  EXPECT_TRUE(close(closure.drag_coefficient(in), 2.746211324963329e-06, 1e-12));
  in.porosity = 0.5;
  EXPECT_TRUE(close(closure.drag_coefficient(in), 2.746211324963329e-06, 1e-12));
  EXPECT_EQ(drag_closure_name(DragClosureKind::MorsiAlexander), "morsi_alexander");
}

}  // namespace
}  // namespace carom
