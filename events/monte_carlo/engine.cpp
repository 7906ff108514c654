// The Monte Carlo engine: steps, actions, what a run shows inside a step, counters. Setup is in
// engine_setup.cpp, one particle's step in particle_step.cpp.
#include "events/monte_carlo/engine.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "events/restored_actions.hpp"

namespace carom {

Vec3 MonteCarloEngine::wrapped(Vec3 r) const {
  const Domain& d = system_.domain;
  for (int k = 0; k < 3; ++k) {
    if (!d.periodic[k]) continue;
    const double length = d.upper[k] - d.lower[k];
    if (r[k] < d.lower[k] || r[k] >= d.upper[k]) {
      r[k] -= length * std::floor((r[k] - d.lower[k]) / length);
      if (r[k] >= d.upper[k]) r[k] = d.lower[k];  // round-off of a value just below lower
    }
  }
  return r;
}

void MonteCarloEngine::add_periodic_action(std::string name, double first_time, double interval,
                                           std::function<void()> action) {
  if (!(interval > 0.0)) throw std::invalid_argument(name + ": the interval must be positive");
  first_time = restored_next_time(restored_action_times_, name, first_time, time_, interval);
  if (computed_ && first_time < step_end_)
    throw std::logic_error(name + ": an action cannot start inside the step under way (at " +
                           std::to_string(first_time) + " s, the step ends at " +
                           std::to_string(step_end_) + " s)");
  actions_.push_back(Action{std::move(name), first_time, interval, std::move(action), {}});
}

void MonteCarloEngine::add_synchronising_action(std::string name, double first_time, double interval,
                                                std::function<void(GlobalStep&)> step) {
  if (!(interval > 0.0)) throw std::invalid_argument(name + ": the interval must be positive");
  if (!(first_time >= time_)) throw std::invalid_argument(name + ": the first step is before the current time");
  first_time = restored_next_time(restored_action_times_, name, first_time, time_, interval);
  if (computed_ && first_time < step_end_)
    throw std::logic_error(name + ": an action cannot start inside the step under way");
  actions_.push_back(Action{std::move(name), first_time, interval, {}, std::move(step)});
}

void MonteCarloEngine::fire_due_actions() {
  for (bool fired = true; fired;) {
    fired = false;
    for (Action& a : actions_) {
      if (a.next_time > time_) continue;
      fired = true;
      if (a.step) {
        // A synchronising action is the gas's hook (the fluid step, a drag or spin kick): the
        // kinetic energy (and spin energy) it gives the particles is work done by the gas.
        ParticleStore& p = system_.particles;
        const double kinetic_before = particles_kinetic_energy();
        GlobalStep step{time_, p, flights_};
        a.step(step);
        if (flights_.size() != p.size()) throw std::logic_error(a.name + " changed the number of flights");
        hold_fixed_particles();
        gas_work_ += particles_kinetic_energy() - kinetic_before;
        if (!step.change.empty()) apply_change(step.change);
      } else {
        a.action();
      }
      a.next_time += a.interval;
    }
  }
}

bool MonteCarloEngine::run_until(double t_end) {
  if (!(t_end >= time_))
    throw std::invalid_argument("run_until: the end time " + std::to_string(t_end) +
                                " s is before the current time " + std::to_string(time_) + " s");
  for (;;) {
    if (computed_) {
      if (t_end < step_end_) {
        time_ = t_end;
        present(time_);
        return true;
      }
      commit_step();
      if (time_ == t_end) return true;
      if (stop_flag_ != nullptr && *stop_flag_ != 0) return false;
    }
    if (time_ >= t_end) return true;
    fire_due_actions();
    double end = time_ + time_step_;
    for (const Action& a : actions_) end = std::min(end, a.next_time);
    step_end_ = end;
    compute_step();
  }
}

void MonteCarloEngine::compute_step() {
  ParticleStore& p = system_.particles;
  const std::size_t n = p.size();
  step_start_ = time_;
  start_rng_ = rng_;
  start_statistics_ = statistics_;
  start_travelling_ = travelling_;
  start_position_ = p.position;
  start_velocity_ = p.velocity;
  start_spin_ = p.spin;
  start_gas_work_ = gas_work_;
  end_gas_work_.resize(n);
  end_position_.resize(n);
  end_velocity_.resize(n);
  end_spin_.resize(n);
  grid_.clear();
  cell_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    cell_[i] = grid_.add(p.position[i], p.species[i], p.radius[i], p.velocity[i], p.spin[i]);
  if (options_.partner == PartnerModel::CellParticle)
    grid_.list_members(cell_, p.species, p.velocity);
  log_.clear();
  log_begin_.assign(n + 1, 0);
  step_bound_exceeded_ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    log_begin_[i] = log_.size();
    step_particle(i, cell_[i]);
  }
  log_begin_[n] = log_.size();
  computed_ = true;

  std::size_t collisions = 0;
  for (const StepEvent& e : log_) collisions += e.partner >= 0 ? 1 : 0;
  const double mean = moving_count_ > 0 ? double(collisions) / double(moving_count_) : 0.0;
  // Judged only on a meaningful count (100 collisions in the step): a few particles colliding
  // twice in one step is chance, not a step too long.
  if (collisions >= 100 && mean > options_.max_collisions_per_step) {
    // Leave the run at the start of this step, as it was.
    const double length = step_end_ - step_start_;
    computed_ = false;
    rng_ = start_rng_;
    step_end_ = step_start_;
    std::ostringstream out;
    out << "Monte Carlo step from t = " << step_start_ << " s of " << length
        << " s: the particles collided " << mean
        << " times each on average, more than max_collisions_per_step = " << options_.max_collisions_per_step
        << ": the partner statistics of the collision cells are frozen over a step, so they lag behind "
           "the particles; set [monte_carlo] time_step below "
        << time_step_ * options_.max_collisions_per_step / mean << " s";
    throw MethodFailure("monte_carlo_step_too_long", out.str());
  }
  max_collisions_per_step_ = std::max(max_collisions_per_step_, mean);
}

void MonteCarloEngine::commit_step() {
  ParticleStore& p = system_.particles;
  statistics_ = start_statistics_;
  travelling_ = start_travelling_;
  gas_work_ = start_gas_work_;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t k = log_begin_[i]; k < log_begin_[i + 1]; ++k) {
      book(log_[k], i, p.species[i], statistics_, travelling_);
      gas_work_ += log_[k].gas_work;
    }
    gas_work_ += end_gas_work_[i];
  }
  derive_pair_counts(statistics_, travelling_);
  ++statistics_.events;
  bound_exceeded_ += step_bound_exceeded_;
  time_ = step_end_;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position[i] = wrapped(end_position_[i]);
    p.velocity[i] = end_velocity_[i];
    p.spin[i] = end_spin_[i];
    p.clock[i] = time_;
  }
  step_start_ = step_end_;
  computed_ = false;
}

void MonteCarloEngine::present(double t) {
  ParticleStore& p = system_.particles;
  statistics_ = start_statistics_;
  travelling_ = start_travelling_;
  gas_work_ = start_gas_work_;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.position[i] = start_position_[i];
    p.velocity[i] = start_velocity_[i];
    p.spin[i] = start_spin_[i];
    p.clock[i] = step_start_;
    for (std::size_t k = log_begin_[i]; k < log_begin_[i + 1] && log_[k].time <= t; ++k) {
      const StepEvent& e = log_[k];
      book(e, i, p.species[i], statistics_, travelling_);
      gas_work_ += e.gas_work;
      p.position[i] = e.position;
      p.velocity[i] = e.velocity;
      p.spin[i] = e.spin;
      p.clock[i] = e.time;
    }
  }
  derive_pair_counts(statistics_, travelling_);
}

void MonteCarloEngine::book(const StepEvent& e, std::size_t i, std::uint32_t s, RunStatistics& st,
                            TravellingCounts& travelling) const {
  st.dissipated_energy += e.dissipated;
  if (e.partner < 0) {
    const std::size_t w = static_cast<std::size_t>(-1 - e.partner);
    st.count_wall(s, w, system_.is_impact(e.approach));
    st.wall_impulse[w] -= e.impulse;
    if (st.tagged.any()) st.tagged.book_wall(static_cast<std::int32_t>(i), w, e.impulse);
    return;
  }
  const std::size_t t = static_cast<std::size_t>(e.partner), species = st.species_count;
  // The fictitious partner is no particle: only the travelling particle's impulse is booked.
  if (st.tagged.any())
    st.tagged.book_pair(static_cast<std::int32_t>(i), -1, s, static_cast<std::uint32_t>(t),
                        e.impulse);
  ++travelling.collisions[s * species + t];
  if (system_.is_impact(e.approach)) ++travelling.impacts[s * species + t];
  const double half_impulse = 0.5 * e.impulse.norm();
  st.pair_impulse[s * species + t] += half_impulse;
  if (s != t) st.pair_impulse[t * species + s] += half_impulse;
  st.virial += 0.5 * e.separation * e.impulse.transpose();
}

void MonteCarloEngine::derive_pair_counts(RunStatistics& st, const TravellingCounts& travelling) const {
  const std::size_t species = st.species_count;
  // Half of the directed counts of the pair, both directions (s-s: its own).
  const auto half = [species](const std::vector<std::uint64_t>& directed, std::size_t s, std::size_t t) {
    return (s == t ? directed[s * species + s] : directed[s * species + t] + directed[t * species + s]) / 2;
  };
  std::uint64_t total = 0;
  for (std::size_t s = 0; s < species; ++s)
    for (std::size_t t = 0; t < species; ++t) {
      st.pair_collisions[s * species + t] = half(travelling.collisions, s, t);
      st.pair_impacts[s * species + t] = half(travelling.impacts, s, t);
      total += travelling.collisions[s * species + t];
    }
  st.pair_events = total / 2;
}

Vec3 MonteCarloEngine::position(std::size_t i) const {
  const ParticleStore& p = system_.particles;
  const double s = time_ - p.clock[i];
  if (s == 0.0) return p.position[i];
  return wrapped(p.position[i] + flight_of(i).displacement(p.velocity[i], s));
}

Vec3 MonteCarloEngine::velocity(std::size_t i) const {
  const ParticleStore& p = system_.particles;
  const double s = time_ - p.clock[i];
  if (s == 0.0) return p.velocity[i];
  return flight_of(i).velocity(p.velocity[i], s);
}

Energies MonteCarloEngine::energies() const {
  Energies e;
  const ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e.translational += 0.5 * p.mass[i] * velocity(i).squaredNorm();
    e.rotational += 0.5 * p.inertia[i] * p.spin[i].squaredNorm();
    e.potential -= p.mass[i] * system_.flight.gravity.dot(position(i));
  }
  e.dissipated = statistics_.dissipated_energy;
  e.gas_work = gas_work_;
  e.flow = flow_energy_;
  // The gas's work on each relax flight from the particle's shown state to now, not yet booked
  // (the same flight, bit for bit, as position() and velocity()).
  if (options_.flight_model == FlightModel::Relax)
    for (std::size_t i = 0; i < p.size(); ++i) {
      Vec3 r = p.position[i], v = p.velocity[i];
      e.gas_work += p.mass[i] * flights_[i].move_booking_gas_work(r, v, time_ - p.clock[i],
                                                                  system_.flight.gravity);
    }
  return e;
}

double MonteCarloEngine::particles_kinetic_energy() const {
  const ParticleStore& p = system_.particles;
  double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    sum += 0.5 * (p.mass[i] * p.velocity[i].squaredNorm() + p.inertia[i] * p.spin[i].squaredNorm());
  return sum;
}

std::vector<MethodQuantity> MonteCarloEngine::quantities() const {
  std::uint64_t travelling = 0;
  for (std::uint64_t c : travelling_.collisions) travelling += c;
  const double per_cell = double(system_.particles.size()) / double(grid_.cell_count());
  return {
      {"time_step", time_step_, "s", "particle time step dt_p of the Monte Carlo method"},
      {"cell_size", grid_.cell_size().minCoeff(), "m", "smallest edge of the collision cells"},
      {"particles_per_cell", per_cell, "", "mean number of particles in a collision cell"},
      {"max_collisions_per_step", max_collisions_per_step_, "",
       "largest mean number of collisions per moving particle in one step"},
      {"travelling_collisions", double(travelling), "",
       "collisions of particles with fictitious partners (each is half a pair collision)"},
      {"thinning_bound_exceeded", double(bound_exceeded_), "",
       "collision trials whose relative speed exceeded its bound (the rate is then too low)"},
  };
}

MonteCarloState MonteCarloEngine::state() const {
  MonteCarloState s;
  s.particles = system_.particles;
  s.flights = flights_;
  s.time = time_;
  s.time_step = time_step_;
  s.cell_size = cell_size_;
  s.max_collisions_per_step = max_collisions_per_step_;
  s.bound_exceeded = bound_exceeded_;
  s.gas_work = computed_ ? start_gas_work_ : gas_work_;
  s.flow_energy = flow_energy_;
  if (computed_) {
    s.particles.position = start_position_;
    s.particles.velocity = start_velocity_;
    s.particles.spin = start_spin_;
    std::fill(s.particles.clock.begin(), s.particles.clock.end(), step_start_);
    s.statistics = start_statistics_;
    s.travelling = start_travelling_;
    s.rng = start_rng_.state();
    s.step_start = step_start_;
    s.step_end = step_end_;
  } else {
    s.statistics = statistics_;
    s.travelling = travelling_;
    s.rng = rng_.state();
    s.step_start = s.step_end = time_;
  }
  for (const Action& a : actions_) s.action_times.emplace_back(a.name, a.next_time);
  return s;
}

}  // namespace carom
