#pragma once
/// The `kick` flight scheme (DESIGN.md section 2): the classic hard-sphere discrete particle
/// method. Between kicks the particles fly ballistic parabolas under gravity alone; every particle
/// step dt_p all particles are synchronised and each velocity gets the drag and pressure-gradient
/// impulse of that step as one explicit (forward Euler) kick,
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
#include <stdexcept>
#include <vector>

#include "core/particles.hpp"
#include "core/relax_flight.hpp"
#include "core/vec3.hpp"

namespace carom {

/// Thrown when explicit drag kicks would be unstable (dt_p > 2 tau for some particle).
class KickUnstable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Explicit drag and pressure-gradient kicks every particle step (see the file comment).
class KickScheme {
 public:
  /// `particle_step`: dt_p, s (> 0); `gravity`: g of the ballistic flights between kicks, m/s^2.
  KickScheme(double particle_step, const Vec3& gravity)
      : particle_step_(particle_step), gravity_(gravity) {}

  /// Throws KickUnstable when dt_p rate_i > 2 (dt_p > 2 tau_i) for some particle; no change.
  void check_stability(const ParticleStore& particles,
                       const std::vector<RelaxFlight>& flights) const;
  /// One kick at a synchronised time: v_i += dt_p (a_i(v_i) - g) for every particle (flights[i]:
  /// its flight of the current fluid step). Checks stability first (throws KickUnstable).
  void kick(ParticleStore& particles, const std::vector<RelaxFlight>& flights) const;

  /// dt_p, the time between kicks, s.
  double particle_step() const { return particle_step_; }

 private:
  double particle_step_;
  Vec3 gravity_;
};

}  // namespace carom
