// The Monte Carlo engine's setup: construction (fresh and from a saved state), validation of
// the system, the default time step and cell size, fixed particles.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "events/monte_carlo/engine.hpp"

namespace carom {
namespace {
/// Mean relative speed of two Maxwellian particles over the rms speed of one, 4 / sqrt(3 pi):
/// <|v1 - v2|> = sqrt(16 T / (pi m)) and v_rms = sqrt(3 T / m).
constexpr double kRelativeOverRms = 1.3029400317411199;
}  // namespace

MonteCarloEngine::MonteCarloEngine(System system, MonteCarloOptions options)
    : system_(std::move(system)), options_(options), rng_(options.seed), start_rng_(options.seed) {
  validate();
  ParticleStore& p = system_.particles;
  const std::size_t n = p.size();
  time_ = n > 0 ? *std::max_element(p.clock.begin(), p.clock.end()) : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (p.clock[i] != time_)
      throw std::invalid_argument(
          "the Monte Carlo method needs every particle's state at one time (the clocks differ)");
  }
  step_start_ = step_end_ = time_;
  flights_.assign(n, RelaxFlight{0.0, system_.flight.gravity});
  hold_fixed_particles();
  statistics_.resize(system_.species.size(), system_.walls.size());
  travelling_.assign(system_.species.size());
  resolve_time_step_and_cells();
}

MonteCarloEngine::MonteCarloEngine(System system, MonteCarloOptions options, MonteCarloState state)
    : system_(std::move(system)), options_(options), rng_(options.seed), start_rng_(options.seed) {
  system_.particles = std::move(state.particles);
  const std::size_t n = system_.particles.size();
  const std::size_t species = system_.species.size();
  if (state.flights.size() != n) throw std::invalid_argument("saved state: one flight per particle is missing");
  if (state.statistics.species_count != species || state.statistics.wall_count != system_.walls.size() ||
      state.travelling.collisions.size() != species * species ||
      state.travelling.impacts.size() != species * species)
    throw std::invalid_argument("saved state: the counters do not match the scene's species and walls");
  validate();
  flights_ = std::move(state.flights);
  statistics_ = std::move(state.statistics);
  travelling_ = std::move(state.travelling);
  rng_.set_state(state.rng);
  time_step_ = state.time_step;
  cell_size_ = state.cell_size;
  max_collisions_per_step_ = state.max_collisions_per_step;
  bound_exceeded_ = state.bound_exceeded;
  gas_work_ = state.gas_work;
  flow_energy_ = state.flow_energy;
  restored_action_times_ = std::move(state.action_times);
  grid_ = CollisionGrid(system_.domain, cell_size_, species);
  resolve_elastic_speed();
  moving_count_ = 0;
  for (std::uint32_t s : system_.particles.species) moving_count_ += system_.species[s].fixed ? 0 : 1;
  time_ = step_start_ = step_end_ = state.step_start;
  if (state.step_end > state.step_start) {
    // The saved step is computed again from its start: the same states, counters and random
    // numbers give the same step, shown at the saved time.
    step_end_ = state.step_end;
    compute_step();
    if (state.time < step_end_) {
      time_ = state.time;
      present(time_);
    } else {
      commit_step();
    }
  }
}

void MonteCarloEngine::validate() const {
  const std::size_t species = system_.species.size();
  if (system_.materials.species_count() != species || system_.materials.wall_count() != system_.walls.size())
    throw std::invalid_argument("the material table does not match the species and walls");
  for (std::size_t s = 0; s < species; ++s) {
    for (std::size_t t = s; t < species; ++t)
      system_.materials.pair(s, t).validate("contact law " + system_.species[s].name + "-" +
                                            system_.species[t].name);
    for (std::size_t w = 0; w < system_.walls.size(); ++w)
      system_.materials.wall(s, w).validate("contact law " + system_.species[s].name + "-wall " +
                                            system_.walls[w].name);
  }
  validate_walls(system_.walls, system_.flight.gravity, system_.domain);
  const ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::ostringstream who;
    who << "particle " << p.id[i] << " (at " << p.position[i].transpose() << " m)";
    if (p.species[i] >= species) throw std::invalid_argument(who.str() + " refers to a species that does not exist");
    if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !p.spin[i].allFinite())
      throw std::invalid_argument(who.str() + " has a non-finite position, velocity or spin");
    if (!(p.radius[i] > 0.0) || !(p.mass[i] > 0.0))
      throw std::invalid_argument(who.str() + " must have positive radius and mass");
    for (int k = 0; k < 3; ++k) {
      const double slack = system_.domain.periodic[k] ? 0.0 : kContactTolerance * p.radius[i];
      if (p.position[i][k] < system_.domain.lower[k] - slack || p.position[i][k] > system_.domain.upper[k] + slack)
        throw std::invalid_argument(who.str() + " lies outside the domain");
    }
    for (const Wall& wall : system_.walls)
      if (wall.gap(p.position[i], p.radius[i]) < -kContactTolerance * p.radius[i])
        throw std::invalid_argument(who.str() + " overlaps wall '" + wall.name + "'");
  }
}

void MonteCarloEngine::resolve_time_step_and_cells() {
  const ParticleStore& p = system_.particles;
  const std::size_t n = p.size();
  const std::size_t species = system_.species.size();
  const double volume = system_.domain.volume();
  double largest_diameter = 0.0;
  for (double a : p.radius) largest_diameter = std::max(largest_diameter, 2.0 * a);
  for (std::uint32_t s : system_.entering_species)
    largest_diameter = std::max(largest_diameter, system_.species.at(s).diameter);
  for (std::uint32_t s : p.species) moving_count_ += system_.species[s].fixed ? 0 : 1;

  cell_size_ = options_.cell_size;
  if (!(cell_size_ > 0.0) && n == 0 && !system_.entering_species.empty())
    throw std::invalid_argument(
        "[monte_carlo] cell_size: the default collision cell holds 32 of the particles present at "
        "the start, and this scene starts with none (they enter through inflows): give cell_size "
        "(m), a few times the mean distance between particles where the flow is");
  if (!(cell_size_ > 0.0)) {
    // 4 largest diameters, or more so that a cell holds 32 particles on average: with k
    // particles a cell, Gaussian partners (fitted to those k) heat an elastic gas by about
    // 0.09/k of its energy per collision (engine.hpp; measured: x 1.44 after 44 collisions per
    // particle with k = 10.6, x 1.06 after 41 with k = 49).
    cell_size_ = n > 0 ? std::max(4.0 * largest_diameter, std::cbrt(32.0 * volume / double(n)))
                       : system_.domain.length().maxCoeff();
  }
  grid_ = CollisionGrid(system_.domain, cell_size_, species);

  time_step_ = options_.time_step;
  if (time_step_ > 0.0) {
    resolve_elastic_speed();
    return;
  }
  // Speed scale: the rms speed of the moving particles, at least sqrt(g d) (a bed at rest under
  // gravity gets going at that speed).
  double square_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (!system_.species[p.species[i]].fixed) square_sum += p.velocity[i].squaredNorm();
  const double rms = moving_count_ > 0 ? std::sqrt(square_sum / double(moving_count_)) : 0.0;
  const double speed = std::max(
      {rms, system_.entering_speed, std::sqrt(system_.flight.gravity.norm() * largest_diameter)});
  if (!(speed > 0.0))
    throw std::invalid_argument(
        "[monte_carlo] time_step: every particle is at rest and there is no gravity, so no default "
        "step can be estimated; give time_step (s)");
  // Collision frequency of each species with every other, Maxwellian estimate with the common
  // speed scale: nu_s = sum_t n_t pi (a_s + a_t)^2 <|v_rel|>.
  std::vector<double> count(species, 0.0);
  for (std::uint32_t s : p.species) count[s] += 1.0;
  double fastest = 0.0;
  for (std::size_t s = 0; s < species; ++s) {
    if (count[s] == 0.0) continue;
    double rate = 0.0;
    for (std::size_t t = 0; t < species; ++t) {
      const double reach = system_.species[s].radius() + system_.species[t].radius();
      rate += count[t] / volume * std::numbers::pi * reach * reach * kRelativeOverRms * speed;
    }
    fastest = std::max(fastest, rate);
  }
  const double crossing = 0.25 * grid_.cell_size().minCoeff() / speed;
  time_step_ = fastest > 0.0 ? std::min(0.1 / fastest, crossing) : crossing;
  resolve_elastic_speed();
}

void MonteCarloEngine::resolve_elastic_speed() {
  elastic_below_speed_ = options_.elastic_below_speed >= 0.0
                             ? options_.elastic_below_speed
                             : system_.flight.gravity.norm() * time_step_ / 20.0;
}

void MonteCarloEngine::hold_fixed_particles() {
  ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (system_.species[p.species[i]].fixed) {
      p.velocity[i] = p.spin[i] = Vec3::Zero();
      flights_[i] = RelaxFlight{};
    }
}

}  // namespace carom
