#pragma once
/// The `kick` flight scheme (core/DESIGN.md, "Particles and flights"): the classic hard-sphere
/// discrete particle method. Between kicks the particles fly ballistic parabolas under gravity
/// alone; every particle step dt_p all particles are synchronised and each velocity gets the drag
/// and pressure-gradient impulse of that step as one explicit (forward Euler) kick,
///   v_i <- v_i + dt_p [a_i(v_i) - g] = v_i + dt_p [(u_i - v_i) / tau_i - grad p_i / rho_p],
/// with a_i(v) = drive_i - rate_i v the particle's flight of the current fluid step (u_i, K_i =
/// m_i rate_i, grad p_i frozen at the step's start by GasCoupling::step; tau_i = 1 / rate_i).
///
/// Order: first order in dt_p. Against the exact relaxation v - w -> (v - w) e^(-dt_p / tau) the
/// kick multiplies the distance to the asymptotic velocity w by (1 - dt_p / tau), a relative
/// error of about (dt_p / tau)^2 / 2 per kick, so of order dt_p / (2 tau) over a relaxation time:
/// dt_p <= tau / 5 keeps it near 10 % or below.
///
/// Stability: |1 - dt_p / tau| <= 1, i.e. dt_p <= 2 tau for every particle. Beyond it each kick
/// overshoots the gas velocity by more than it closes, and velocities grow without bound. That
/// failure is shown, not hidden: check_stability throws KickUnstable, naming the particle and the
/// remedies (the `relax` flight, exact for any step; or a smaller flight.particle_step).
///
/// Spin forces (fluid/spin_forces.hpp), when a scene asks for them, are kicks of the same kind:
/// at each kick, from the velocity and spin of that moment and the gas velocity u_i frozen at
/// the fluid step,
///   v_i <- v_i + dt_p F_L(u_i - v_i, Omega_rel) / m_i,   w_i <- w_i + dt_p T(Omega_rel) / I_i,
/// with Omega_rel = -w_i (carom resolves no gas vorticity at the particle's scale). Drag, lift
/// and torque all use the state before the kick (one explicit Euler step of the whole force
/// system), so the scheme stays first order in dt_p. The torque kick is stable while
/// dt_p |T| / (I |Omega_rel|) <= 2 (the secant decay rate of the spin): beyond it a kick
/// reverses the spin by more than it had, and check_stability refuses it as it refuses the drag.
/// Gas work: the scheme itself books none; the methods that call it (event-driven and Monte
/// Carlo kick flights) book the kinetic and spin energy each kick changes as gas work
/// (Energies::gas_work), so the drag's, the lift's and the torque's work are all in the books.
#include <stdexcept>
#include <vector>

#include "core/particles.hpp"
#include "core/relax_flight.hpp"
#include "core/vec3.hpp"
#include "spin_forces.hpp"

namespace carom {

/// Thrown when explicit drag kicks would be unstable (dt_p > 2 tau for some particle).
class KickUnstable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The spin forces a kick applies and the gas properties they need.
struct SpinForceKicks {
  SpinForceSettings models;       ///< Which lift and torque (none by default).
  double gas_density = 1.2;       ///< rho_g, kg/m^3.
  double gas_viscosity = 1.8e-5;  ///< mu_g, Pa s.
};

/// Explicit drag and pressure-gradient kicks every particle step (see the file comment).
class KickScheme {
 public:
  /// `particle_step`: dt_p, s (> 0); `gravity`: g of the ballistic flights between kicks, m/s^2;
  /// `spin`: the spin forces to kick with as well (none by default).
  KickScheme(double particle_step, const Vec3& gravity, SpinForceKicks spin = {})
      : particle_step_(particle_step), gravity_(gravity), spin_(spin) {}

  /// Throws KickUnstable when dt_p rate_i > 2 (dt_p > 2 tau_i) for some particle, or when the
  /// torque's secant decay rate times dt_p exceeds 2 (torque on); no change. With
  /// `longitudinal_rates` (GasCoupling::longitudinal_rates: (1/m) d|F|/d|s| per particle, 1/s),
  /// the limit is 2 / that rate instead: when the drag is refreshed before every kick
  /// (dt_p >= the fluid step) the kicks are explicit Euler steps of the nonlinear drag, whose
  /// departure from the terminal velocity grows beyond it (2 m/(dF/ds) = 1.29 tau for a 0.5 mm
  /// glass bead settling in air at Re = 124), while 2 tau is the limit of kicks at a frozen rate.
  /// The check is local (the rates of the state reached), so a transient overshoot of the
  /// terminal velocity, where the limit is lower, may refuse a step a few % below it.
  void check_stability(const ParticleStore& particles, const std::vector<RelaxFlight>& flights,
                       const std::vector<double>* longitudinal_rates = nullptr) const;
  /// One kick at a synchronised time: v_i += dt_p (a_i(v_i) - g) for every particle (flights[i]:
  /// its flight of the current fluid step), plus the spin forces when some are on, which need
  /// `gas_velocity` (u_i at each particle, frozen at the fluid step, m/s; may be null when the
  /// spin forces are off). Checks stability first (throws KickUnstable).
  void kick(ParticleStore& particles, const std::vector<RelaxFlight>& flights,
            const std::vector<Vec3>* gas_velocity = nullptr) const;
  /// The spin-force input of particle i with gas velocity u (Omega_rel = -w_i).
  SpinForceInput spin_input(const ParticleStore& particles, std::size_t i, const Vec3& u) const;

  /// dt_p, the time between kicks, s.
  double particle_step() const { return particle_step_; }
  /// The spin forces kicked with.
  const SpinForceKicks& spin_forces() const { return spin_; }

 private:
  double particle_step_;
  Vec3 gravity_;
  SpinForceKicks spin_;
};

}  // namespace carom
