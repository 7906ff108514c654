#include "kick_scheme.hpp"

#include <cmath>
#include <sstream>

namespace carom {

void KickScheme::check_stability(const ParticleStore& particles,
                                 const std::vector<RelaxFlight>& flights) const {
  const double dt_p = particle_step_;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (flights[i].rate * dt_p <= 2.0) continue;
    const double tau = 1.0 / flights[i].rate;
    std::ostringstream out;
    out << "kick flights are unstable: particle " << particles.id[i]
        << " has a drag relaxation time tau = m/K = " << tau
        << " s, and the particle step dt_p = " << dt_p
        << " s exceeds 2 tau: each explicit drag kick overshoots the gas velocity by a factor |1 - "
           "dt_p/tau| = "
        << std::abs(1.0 - dt_p / tau)
        << " > 1, so velocities grow without bound. Remedy: flight.model = \"relax\" (exact for "
           "any step), or "
           "flight.particle_step below "
        << 2.0 * tau << " s (tau / 5 or less for first-order accuracy).";
    throw KickUnstable(out.str());
  }
}

void KickScheme::kick(ParticleStore& particles, const std::vector<RelaxFlight>& flights) const {
  check_stability(particles, flights);
  const double dt_p = particle_step_;
  for (std::size_t i = 0; i < particles.size(); ++i)
    particles.velocity[i] += dt_p * (flights[i].acceleration(particles.velocity[i]) - gravity_);
}

}  // namespace carom
