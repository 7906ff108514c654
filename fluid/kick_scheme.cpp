#include "kick_scheme.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace carom {

SpinForceInput KickScheme::spin_input(const ParticleStore& particles, std::size_t i,
                                      const Vec3& u) const {
  SpinForceInput in;
  in.slip = u - particles.velocity[i];
  in.relative_rotation = -particles.spin[i];  // curl u = 0 at the particle's scale
  in.diameter = 2.0 * particles.radius[i];
  in.gas_density = spin_.gas_density;
  in.gas_viscosity = spin_.gas_viscosity;
  return in;
}

void KickScheme::check_stability(const ParticleStore& particles,
                                 const std::vector<RelaxFlight>& flights,
                                 const std::vector<double>* longitudinal_rates) const {
  const double dt_p = particle_step_;
  const bool tangent =
      longitudinal_rates != nullptr && longitudinal_rates->size() == particles.size();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const double limiting_rate =
        tangent ? std::max(flights[i].rate, (*longitudinal_rates)[i]) : flights[i].rate;
    if (limiting_rate * dt_p <= 2.0) continue;
    const double tau = 1.0 / flights[i].rate;
    std::ostringstream out;
    out.precision(4);
    out << "kick flights are unstable: particle " << particles.id[i]
        << " has a drag relaxation time tau = m/K = " << tau << " s";
    if (limiting_rate > flights[i].rate)
      out << " and, as its drag grows faster than the slip, a longitudinal rate (1/m) dF/ds = "
          << limiting_rate
          << " 1/s (the drag is refreshed before every kick: dt_p >= the fluid step)";
    out << "; the particle step dt_p = " << dt_p << " s exceeds the largest stable step "
        << 2.0 / limiting_rate
        << " s (2 m/(dF/ds); 2 tau at a frozen drag): each explicit drag kick overshoots the "
           "terminal velocity by a factor |1 - dt_p x rate| = "
        << std::abs(1.0 - dt_p * limiting_rate)
        << " > 1, so velocities grow without bound. Remedy: flight.model = \"relax\" (exact for "
           "any step), or flight.particle_step below "
        << 2.0 / limiting_rate << " s (tau / 5 or less for first-order accuracy).";
    throw KickUnstable(out.str());
  }
  if (spin_.models.torque == RotationalTorque::None) return;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const double spin = particles.spin[i].norm();
    if (spin == 0.0) continue;
    // Omega_rel = -w: |T| / (I |w|) is the rate at which the kick takes spin away.
    const SpinForceInput in = spin_input(particles, i, Vec3::Zero());
    const double rate =
        rotational_torque(spin_.models.torque, in).norm() / (particles.inertia[i] * spin);
    if (rate * dt_p <= 2.0) continue;
    std::ostringstream out;
    out << "kick flights are unstable: the hydrodynamic torque (gas.rotational_torque) slows the "
           "spin of particle "
        << particles.id[i] << " (" << spin << " rad/s) at the rate |T|/(I |w|) = " << rate
        << " 1/s, and the particle step dt_p = " << dt_p
        << " s exceeds 2 / rate: each explicit torque kick would reverse the spin by more than it "
           "had. Remedy: flight.particle_step below "
        << 2.0 / rate << " s (a tenth of that for first-order accuracy).";
    throw KickUnstable(out.str());
  }
}

void KickScheme::kick(ParticleStore& particles, const std::vector<RelaxFlight>& flights,
                      const std::vector<Vec3>* gas_velocity) const {
  check_stability(particles, flights);
  const double dt_p = particle_step_;
  if (!spin_.models.any()) {
    for (std::size_t i = 0; i < particles.size(); ++i)
      particles.velocity[i] += dt_p * (flights[i].acceleration(particles.velocity[i]) - gravity_);
    return;
  }
  if (gas_velocity == nullptr || gas_velocity->size() != particles.size())
    throw std::logic_error("KickScheme::kick: spin forces need the gas velocity at every particle");
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const SpinForceInput in = spin_input(particles, i, (*gas_velocity)[i]);
    const Vec3 lift = magnus_lift_force(spin_.models.lift, in);
    const Vec3 torque = rotational_torque(spin_.models.torque, in);
    particles.velocity[i] += dt_p * (flights[i].acceleration(particles.velocity[i]) - gravity_ +
                                     lift / particles.mass[i]);
    particles.spin[i] += (dt_p / particles.inertia[i]) * torque;
  }
}

}  // namespace carom
