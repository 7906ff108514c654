#pragma once
/// The Monte Carlo collision method (Oesterle & Petitjean 1991/1993; Sommerfeld 2001;
/// core/DESIGN.md, "Methods"), the third CollisionMethod: particles move in time steps on exact
/// flights; each step, every cell of a collision grid records the number density and velocity
/// statistics of each species, and every particle collides, as a Poisson process of the
/// collision frequency nu, with fictitious partners drawn from the statistics of its cell.
/// Only the travelling particle changes (the partner is not a particle). Walls stay exact.
///
/// One step from t to t + h of particle i (particle_step.cpp):
///   - the rate of candidate collisions with species t is Lambda_t = c pi (R1 + R0)^2 n g B_t,
///     with c = sqrt(2) (frequency "mean_velocity") or 1 ("mean_relative_speed"), g the
///     contact value, and B_t a bound of the speed in nu over the rest of the step; a candidate
///     is kept with probability |V1 - <V0>| / B_t or |V1 - V0| / B_t (V0 drawn for it): thinning,
///     so collisions form a Poisson process of rate nu exactly, also while gravity or drag
///     changes V1 during the step, and the probability of at least one collision in a step is
///     1 - exp(-nu h) as in the paper. A particle may collide more than once in a step (the
///     paper's at most one collision per step undercounts by (1 - e^-x)/x, x = nu h);
///   - wall impacts are exact event times (ballistic or relax contact times of the walls),
///     taken in time order with the collisions;
///   - flights are exact: ballistic under gravity, or the RelaxFlight of the current fluid
///     step (RelaxFlight::velocity / displacement over each stretch), whose gas work is booked
///     exactly (RelaxFlight::move_booking_gas_work), as is the kinetic energy that synchronising
///     actions (the gas's kicks) give: kinetic + potential + dissipated - gas work is constant.
/// Energy of an elastic gas: each collision gives the particle, on average, half the energy
/// difference with its partner, which cancels over the gas when the partners (weighted by
/// |V1 - V0|) are the gas's own velocities. Gaussian partners fitted to the k particles of a
/// cell (the default, the published model) are not: an elastic gas heats by about 0.09/k of
/// its energy per collision (measured: 0.0083, 0.0049, 0.0013 per collision at k = 10.6, 20.6,
/// 49; scenarios/chart/CHARTS.md). Partners drawn from the cell's particles
/// (PartnerModel::CellParticle) remove it. Either way the energy random-walks (the partner is
/// fictitious): sd about sqrt(c / N) of it after c collisions per particle of N particles.
/// Step boundaries: every time_step, cut to land on every action's time. run_until's end is
/// not a boundary: the step holding it is computed whole and the run shows the particles as of
/// their last event before it (step_log.hpp), so where a run is cut into calls never changes
/// what it computes (resumed runs continue bit for bit).
///
/// Pieces, one file each: options.hpp, collision_grid.* (cell statistics), partner_sampling.*
/// (partner velocity, impact geometry, contact value), particle_step.cpp (one particle's
/// step), engine_setup.cpp (construction, validation, default step and cells), engine.cpp
/// (steps, actions, views, counters), engine_state_io.cpp (checkpoints), flow_change.cpp
/// (particles leaving and entering).
#include <csignal>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "core/relax_flight.hpp"
#include "core/rng.hpp"
#include "core/system.hpp"
#include "events/method.hpp"
#include "events/monte_carlo/collision_grid.hpp"
#include "events/monte_carlo/options.hpp"
#include "events/monte_carlo/step_log.hpp"
#include "events/statistics.hpp"

namespace carom {

/// Collisions and impacts of travelling particles of species s with partners of species t,
/// [s * S + t] (directed: the pair counts take half of each).
struct TravellingCounts {
  std::vector<std::uint64_t> collisions;
  std::vector<std::uint64_t> impacts;
  void assign(std::size_t species) {
    collisions.assign(species * species, 0);
    impacts.assign(species * species, 0);
  }
  bool operator==(const TravellingCounts&) const = default;
};

/// Everything a Monte Carlo run needs to continue exactly: the state at the start of the
/// current step (its particles, counters, random generator), where that step ends, and the
/// current time inside it.
struct MonteCarloState {
  ParticleStore particles;                 ///< At step_start (clocks = step_start).
  std::vector<RelaxFlight> flights;        ///< Each particle's flight in the step.
  RunStatistics statistics;                ///< At step_start.
  TravellingCounts travelling;             ///< Directed counts at step_start.
  std::string rng;                         ///< Random generator at step_start (Rng::state()).
  double time = 0;                         ///< Current time, s.
  double step_start = 0;                   ///< s.
  double step_end = 0;                     ///< s; == step_start when no step is under way.
  double time_step = 0;                    ///< The resolved dt_p, s.
  double cell_size = 0;                    ///< The resolved cell size, m.
  double max_collisions_per_step = 0;      ///< Largest mean collisions per particle in a step so far.
  std::uint64_t bound_exceeded = 0;        ///< Thinning trials whose speed exceeded the bound.
  double gas_work = 0;  ///< Work of the gas forces on the particles by step_start, J.
  double flow_energy = 0;  ///< Energy brought in by entering particles minus taken out, J.
  std::vector<std::pair<std::string, double>> action_times;  ///< Next time of each action, s.
};

void write_monte_carlo_state(const h5::Group& group, const MonteCarloState& state);
MonteCarloState read_monte_carlo_state(const h5::Group& group);

class MonteCarloEngine final : public CollisionMethod {
 public:
  /// Validates the system (laws, walls, states; overlaps between particles are allowed: the
  /// method has no excluded volume), resolves the time step and cell size, bins the particles.
  MonteCarloEngine(System system, MonteCarloOptions options);
  /// Continues a saved run (`system` supplies box, walls, species, laws). The saved time step
  /// and cell size are used, whatever the options say.
  MonteCarloEngine(System system, MonteCarloOptions options, MonteCarloState state);

  std::string_view kind() const override { return "monte_carlo"; }
  bool run_until(double t_end) override;
  void set_stop_flag(const volatile std::sig_atomic_t* flag) override { stop_flag_ = flag; }
  void add_periodic_action(std::string name, double first_time, double interval,
                           std::function<void()> action) override;
  void add_synchronising_action(std::string name, double first_time, double interval,
                                std::function<void(GlobalStep&)> step) override;

  double time() const override { return time_; }
  const System& system() const override { return system_; }
  Vec3 position(std::size_t i) const override;
  Vec3 velocity(std::size_t i) const override;
  Vec3 spin(std::size_t i) const override { return system_.particles.spin[i]; }
  Energies energies() const override;
  /// Counters: pair_collisions{s,t} is half the collisions that travelling particles of s had
  /// with partners of t plus those of t with s (for s = t: half those of s with s), rounded
  /// down, so that 2 pair(s,s)/N_s and pair(s,t)/N_s per unit time are collision frequencies
  /// per particle as for the event-driven method (one collision there gives two particles
  /// one each); pair_impulse and the virial likewise take half of each travelling collision.
  /// events: steps completed; pair_events: half the travelling collisions.
  const RunStatistics& statistics() const override { return statistics_; }
  std::vector<MethodQuantity> quantities() const override;
  /// Tags the bodies in the shown counters and in those of the step start (a step is booked
  /// from there).
  void tag_bodies(const std::vector<std::uint64_t>& ids) override {
    CollisionMethod::tag_bodies(ids);
    start_statistics_.tagged = statistics_.tagged;
  }
  void save_state(const h5::Group& group) const override { write_monte_carlo_state(group, state()); }

  MonteCarloState state() const;
  const MonteCarloOptions& options() const { return options_; }
  double time_step() const { return time_step_; }
  const CollisionGrid& grid() const { return grid_; }
  /// Collisions of travelling particles of species s with partners of species t, [s * S + t].
  const std::vector<std::uint64_t>& travelling_collisions() const { return travelling_.collisions; }
  /// Each particle's current flight.
  const std::vector<RelaxFlight>& flights() const { return flights_; }

 private:
  struct Action {
    std::string name;
    double next_time = 0;  ///< s.
    double interval = 0;   ///< s.
    std::function<void()> action;         ///< Periodic (reads only).
    std::function<void(GlobalStep&)> step;  ///< Synchronising.
  };

  void validate() const;
  void resolve_time_step_and_cells();
  void resolve_elastic_speed();
  /// Fires every action due at the current time (no step under way).
  void fire_due_actions();
  /// Removes and adds particles (a flow step, no step under way; flow_change.cpp).
  void apply_change(const ParticleChange& change);
  /// Computes the step from time_ to step_end_ (everything synchronised at time_).
  void compute_step();
  /// One particle's step (particle_step.cpp): reads start_*, writes end_* and the log.
  void step_particle(std::size_t i, std::int32_t cell);
  /// Ends the computed step: everything synchronised at step_end_.
  void commit_step();
  /// Shows the computed step at time t (inside it): delayed states and counters.
  void present(double t);
  /// Adds one logged event of a particle of species s to the counters.
  void book(const StepEvent& event, std::size_t i, std::uint32_t s, RunStatistics& statistics,
            TravellingCounts& travelling) const;
  /// Sets the symmetric pair counts, pair impacts and pair_events from the directed counts.
  void derive_pair_counts(RunStatistics& statistics, const TravellingCounts& travelling) const;
  void hold_fixed_particles();
  /// Translational and rotational kinetic energy of the particles' stored states, J.
  double particles_kinetic_energy() const;
  /// The flight particle i flies now (ballistic under gravity unless relax flights).
  RelaxFlight flight_of(std::size_t i) const {
    return options_.flight_model == FlightModel::Relax ? flights_[i]
                                                       : RelaxFlight{0.0, system_.flight.gravity};
  }
  /// Position with periodic axes wrapped into the box.
  Vec3 wrapped(Vec3 r) const;

  System system_;                 ///< particles: the states shown at time_ (delayed inside a step).
  MonteCarloOptions options_;
  double time_step_ = 0;          ///< dt_p, s.
  double cell_size_ = 0;          ///< m.
  double elastic_below_speed_ = 0;  ///< Wall impacts slower than this are elastic, m/s.
  CollisionGrid grid_;
  Rng rng_;
  Rng start_rng_;                 ///< At the start of the computed step.
  std::vector<RelaxFlight> flights_;
  std::vector<Action> actions_;
  std::vector<std::pair<std::string, double>> restored_action_times_;

  double time_ = 0;               ///< s.
  double step_start_ = 0;         ///< s.
  double step_end_ = 0;           ///< s.
  bool computed_ = false;         ///< A step [step_start_, step_end_] is computed.
  // The computed step: start state, end state, and each particle's events (log_begin_[i] to
  // log_begin_[i + 1]).
  std::vector<Vec3> start_position_, start_velocity_, start_spin_;
  std::vector<Vec3> end_position_, end_velocity_, end_spin_;
  /// Gas work on each particle after its last event in the step, J.
  std::vector<double> end_gas_work_;
  std::vector<StepEvent> log_;
  std::vector<std::size_t> log_begin_;
  std::vector<std::int32_t> cell_;  ///< Each particle's collision cell at the step start.

  /// Work of the gas forces on the particles, J: the relax flights' exact integrals up to each
  /// particle's shown state (energies() adds the rest of each flight to time_) and the kinetic
  /// energy that synchronising actions (the gas's kicks and fluid steps) gave.
  double gas_work_ = 0;
  double start_gas_work_ = 0;      ///< At step_start_, J.
  /// Energy that entering particles brought minus what leaving ones took out, J (changes only
  /// between steps).
  double flow_energy_ = 0;
  RunStatistics statistics_;       ///< As shown at time_.
  RunStatistics start_statistics_;  ///< At step_start_.
  TaggedImpulses& tagged_impulses() override { return statistics_.tagged; }
  TravellingCounts travelling_, start_travelling_;
  double max_collisions_per_step_ = 0;
  std::uint64_t bound_exceeded_ = 0;       ///< Committed steps.
  std::uint64_t step_bound_exceeded_ = 0;  ///< In the computed step.
  /// Per-species work arrays of step_particle (kept to spare allocations).
  struct Scratch {
    std::vector<PartnerStatistics> partners;
    std::vector<double> rate_per_speed, bound, candidate_rate;
  } scratch_;
  std::size_t moving_count_ = 0;  ///< Particles not of a fixed species.
  const volatile std::sig_atomic_t* stop_flag_ = nullptr;
};

}  // namespace carom
