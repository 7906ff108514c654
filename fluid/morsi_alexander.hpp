#pragma once
/// The Morsi & Alexander (1972) single-sphere drag: a closure for dilute flows with no porosity
/// correction (`gas.drag = "morsi_alexander"`).
///
/// Morsi, S.A. & Alexander, A.J. (1972), "An investigation of particle trajectories in two-phase
/// flow systems", J. Fluid Mech. 55:193. C_D(Re) = a1 + a2 / Re + a3 / Re^2 on eight ranges of
/// Re = rho_g d |u - v| / mu_g (the single sphere's: no porosity in it), fitted to the standard
/// drag curve of a smooth sphere for Re < 5e4; above 5e4 the last range is extrapolated (the
/// drag crisis near 3e5 is not in it). The pieces meet only approximately at the range ends
/// (jumps of up to about 1 % in C_D).
///   Re <= 0.1          0        24        0
///   0.1 < Re <= 1      3.690    22.73     0.0903
///   1 < Re <= 10       1.222    29.1667   -3.8889
///   10 < Re <= 100     0.6167   46.50     -116.67
///   100 < Re <= 1000   0.3644   98.33     -2778
///   1000 < Re <= 5000  0.357    148.62    -4.75e4
///   5000 < Re <= 1e4   0.46     -490.546  5.787e5
///   Re > 1e4           0.5191   -1662.5   5.4167e6
/// The force on a particle is F = C_D (pi/8) d^2 rho_g |u - v| (u - v) whatever the local
/// porosity: meant for dilute flows (solid fractions of 1e-3 and below), where a porosity
/// function would change K by less than its own uncertainty. In carom's K form
/// (fluid/drag.hpp): K = 3 pi mu_g d (C_D Re / 24).
#include "drag.hpp"

namespace carom {

/// Morsi & Alexander C_D(Re) (table above), dimensionless; Re > 0.
double morsi_alexander_cd(double reynolds);
/// Morsi & Alexander C_D Re / 24, the factor on the Stokes drag 3 pi mu d |u - v|; 1 at Re -> 0.
double morsi_alexander_factor(double reynolds);
/// K of one particle, kg/s: 3 pi mu_g d (C_D Re / 24) with Re = rho_g d |u - v| / mu_g (in.porosity
/// is not used).
double morsi_alexander_drag(const DragInput& in);

}  // namespace carom
