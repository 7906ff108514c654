// Particles leaving and entering the Monte Carlo method (inflow, outflow), between two steps:
// the per-step arrays are sized again by the next step, so only the flights follow.
#include "events/monte_carlo/engine.hpp"
#include "events/particle_change.hpp"

namespace carom {

void MonteCarloEngine::apply_change(const ParticleChange& change) {
  check_particle_change(change, system_, time_);
  ParticleStore& p = system_.particles;
  flow_energy_ += change_energy(change, p, system_.flight.gravity);
  follow_change(flights_, change, RelaxFlight{0.0, system_.flight.gravity});
  apply_particle_change(change, p, statistics_.tagged);
  moving_count_ = 0;
  for (std::uint32_t s : p.species) moving_count_ += system_.species[s].fixed ? 0 : 1;
}

}  // namespace carom
