#pragma once
/// The damping of the Hertz contact that gives a binary impact a chosen restitution e.
///
/// With the Tsuji-type dashpot of LIGGGHTS' Hertz model, gamma_n = 2 sqrt(5/6) beta sqrt(S_n m*),
/// S_n = 2 E* sqrt(R* delta), the normal equation m* delta'' = -k_h delta^3/2 - gamma_n delta'
/// (k_h = 4/3 E* sqrt(R*)) becomes, in units of delta* = (m* v0^2 / k_h)^2/5 and delta*/v0,
///   x'' = -x^3/2 - zeta x^1/4 x',  x(0) = 0, x'(0) = 1,  zeta = sqrt(5) beta,
/// so the restitution -x'(end) depends on beta alone, not on the impact speed or the materials.
namespace carom {

/// The restitution of the dimensionless Hertz impact with damping parameter beta >= 0, computed
/// by integrating the equation above (classical Runge-Kutta, 2e-4 time units per step, to the
/// return to x = 0 located by interpolation; accurate to ~1e-6, the x^1/4 at the start limits
/// the order); beta = 0 gives 1 to 1e-11.
double hertz_restitution(double beta);

/// The beta >= 0 for which hertz_restitution(beta) = e (e in (0, 1]), by bisection to 1e-10
/// relative (results are remembered: a scene has few distinct e).
double hertz_damping_for_restitution(double e);

/// LIGGGHTS' formula: beta = -ln e / sqrt(ln^2 e + pi^2) (exact for the linear spring-dashpot,
/// an approximation for Hertz); e in (0, 1].
double liggghts_damping(double e);

}  // namespace carom
