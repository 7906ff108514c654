#pragma once
/// The event loop: exact hard-sphere dynamics from event to event.
#include <csignal>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/cell_grid.hpp"
#include "core/relax_flight.hpp"
#include "core/system.hpp"
#include "events/calendar.hpp"
#include "events/collapse.hpp"
#include "events/event.hpp"
#include "events/pair_batch.hpp"
#include "events/statistics.hpp"

namespace carom {

/// How particles move between events (DESIGN.md section 2).
enum class FlightModel {
  /// Under gravity only (System::flight). Drag, if any, comes as velocity kicks from a
  /// synchronising action (the `kick` scheme).
  Ballistic,
  /// Each particle flies its own RelaxFlight (gravity plus a linear drag), set by a
  /// synchronising action (the fluid step); predictions never reach past the next one.
  Relax,
};

struct SimulatorOptions {
  FlightModel flight_model = FlightModel::Ballistic;  ///< See FlightModel.
  CollapseOptions collapse;   ///< TC model, low-speed elasticity, stall detector.
  /// How species are split into grid levels: < 0 picks the split with the least expected
  /// prediction work (default); > 0 gives a size its own level when it is below this ratio of
  /// the level above; 0 puts everything in one grid.
  double grid_level_ratio = -1.0;
  /// Grid cells per largest diameter of a level (1..3): smaller cells mean fewer candidate
  /// partners per prediction but more cell crossings and cell visits. 0 (default): chosen per
  /// level by the grid's cost model (1 for a monodisperse system).
  int grid_subdivision = 0;
  /// Check the invariants at every collision (no overlap, momentum balance). On by default in
  /// debug builds; costs a few percent.
#ifdef NDEBUG
  bool check_invariants = false;
#else
  bool check_invariants = true;
#endif
};

/// Kinetic, potential and dissipated energy at the current time, J.
struct Energies {
  double translational = 0;  ///< sum m v^2 / 2.
  double rotational = 0;     ///< sum I w^2 / 2.
  double potential = 0;      ///< sum -m g . r (positions folded into the box).
  double dissipated = 0;     ///< Lost in collisions since the start.
  /// translational + rotational + potential + dissipated: constant in an exact run.
  double total() const { return translational + rotational + potential + dissipated; }
};

/// What a synchronising action sees and may change: every particle advanced to `time`.
struct GlobalStep {
  double time;                        ///< s.
  ParticleStore& particles;           ///< States as of `time`; velocities may be changed.
  std::vector<RelaxFlight>& flights;  ///< Each particle's flight until the next step (Relax).
};

/// A periodic global event: `action` (or `step`) runs at first, first + interval, ...
struct PeriodicAction {
  std::string name;                 ///< For diagnostics ("sample", "checkpoint").
  double next_time = kNever;        ///< Next time it fires, s.
  double interval = kNever;         ///< Period, s.
  std::function<void()> action;     ///< Reads the run but changes no particle.
  /// A synchronising action: every particle is advanced to the event time first, then this
  /// may change velocities and flights, then every particle's events are predicted again.
  std::function<void(GlobalStep&)> step;
};

/// Everything needed to continue a run exactly (bit for bit) from where it stopped: the
/// particles' stored (delayed) states, their grid cells, the calendar's particle entries, the
/// counters and the clocks. The System's other parts (box, walls, species, laws) come from the
/// scene again.
struct EngineState {
  ParticleStore particles;                          ///< In the simulator's internal order.
  std::vector<std::array<int, 3>> cells;            ///< Grid cell of each particle.
  /// Each particle's place in its cell's list (HierarchicalGrid::place_in_cell); empty: the
  /// lists are rebuilt in particle order (checkpoints written before it was saved).
  std::vector<std::int32_t> places;
  std::vector<Event> events;                        ///< Each particle's next pair/wall event.
  std::vector<Event> crossings;                     ///< Each particle's next cell crossing.
  std::vector<RelaxFlight> flights;                 ///< Relax model: each particle's flight.
  double time = 0;                                  ///< s.
  double last_particle_event = 0;                   ///< s.
  RunStatistics statistics;
  std::vector<double> stall_window_start;           ///< s.
  std::vector<std::uint32_t> stall_count;
  double stall_window = 0;                          ///< s.
  std::vector<std::pair<std::string, double>> action_times;  ///< Next time of each action, s.
};

class Simulator {
 public:
  /// Takes the system, validates the initial state (throws std::invalid_argument), builds the
  /// grid and predicts every particle's first event.
  explicit Simulator(System system, SimulatorOptions options = {});

  /// Continues a saved run: `system` supplies box, walls, species and laws (its particles are
  /// ignored), `state` everything that moves. Actions added later under a saved name resume at
  /// their saved next time.
  Simulator(System system, SimulatorOptions options, EngineState state);

  /// A copy of the complete dynamic state (see EngineState).
  EngineState state() const;

  /// Processes every event up to time t_end (s) and stops there. Returns true when it got
  /// there, false when the stop flag (see set_stop_flag) was raised first: then the run stands
  /// at its last processed event, in a consistent state that can be checkpointed and resumed.
  /// Throws InelasticCollapse when the stall detector fires.
  bool run_until(double t_end);

  /// A flag (set by a signal handler, say) that run_until checks every few thousand events.
  void set_stop_flag(const volatile std::sig_atomic_t* flag) { stop_flag_ = flag; }

  /// Registers an action to run at first_time and then every interval seconds (a global event).
  void add_periodic_action(std::string name, double first_time, double interval,
                           std::function<void()> action);

  /// Registers a synchronising action (see PeriodicAction::step): the fluid step, drag kicks.
  /// With FlightModel::Relax, predictions never reach past the next one, so a Relax run needs
  /// at least one.
  void add_synchronising_action(std::string name, double first_time, double interval,
                                std::function<void(GlobalStep&)> step);

  /// Each particle's current flight (FlightModel::Relax), in the simulator's order.
  const std::vector<RelaxFlight>& flights() const { return flights_; }

  /// The current time, s.
  double time() const { return time_; }
  /// Box, walls, species, laws and particles. The particle store is up to date (each state as
  /// of its particle's clock) whenever run_until is not running, and inside actions; read the
  /// state at the current time through position(i), velocity(i) and spin(i).
  const System& system() const { return system_; }
  const SimulatorOptions& options() const { return options_; }
  const RunStatistics& statistics() const { return statistics_; }
  const HierarchicalGrid& grid() const { return grid_; }
  std::size_t particle_count() const { return system_.particles.size(); }

  /// Particle i's position at the current time, m (its stored state is not changed).
  Vec3 position(std::size_t i) const;
  /// Particle i's velocity at the current time, m/s.
  Vec3 velocity(std::size_t i) const;
  /// Particle i's spin, rad/s.
  const Vec3& spin(std::size_t i) const { return body_[i].spin; }
  Energies energies() const;

  /// The event particle i is waiting for (its calendar entry): the earlier of its next
  /// collision and its next cell crossing.
  Event next_event(std::size_t i) const {
    const Agenda& a = agenda_[i];
    return a.crossing.time <= a.collision.time ? a.crossing : a.collision;
  }
  /// next_event(i) for every particle.
  std::vector<Event> predicted_events() const {
    std::vector<Event> all(agenda_.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = next_event(i);
    return all;
  }

 private:
  /// Predicts particle i's next collision, and its next cell crossing when its trajectory is
  /// new (a particle whose predicted partner moved away keeps its crossing).
  void predict(std::int32_t i, bool new_trajectory = true);
  /// Puts particle i's earlier event (collision or crossing) in the calendar.
  void schedule(std::int32_t i);
  template <bool kGravity>
  void predict_with(std::int32_t i);
  /// Contact time of particles i and j (periodic images considered), or kNever.
  template <bool kGravity>
  double pair_time(std::int32_t i, std::int32_t j) const;
  double wall_time(std::int32_t i, const Wall& wall) const;
  Event cell_crossing(std::int32_t i) const;
  /// cell_crossing without gravity (straight flights), bit for bit the same event.
  Event straight_cell_crossing(std::int32_t i) const;
  /// Earliest contact of i with the particles of the given cells of its own level, if earlier
  /// than best_time (updated); returns the partner or -1.
  template <bool kGravity>
  std::int32_t scan_cells(std::int32_t i, const std::int32_t* cells, int count, bool wrapped,
                          double& best_time) const;
  /// After a crossing, looks for partners only in the cells that just came into reach.
  template <bool kGravity>
  void predict_after_crossing(std::int32_t i, int axis, int direction);

  /// Relax flights: every prediction of particle i (cell crossing when new_trajectory).
  void predict_relax(std::int32_t i, bool new_trajectory);
  /// Contact time of i and j if before `limit` (and the horizon), else kNever; s.
  double relax_pair_time(std::int32_t i, std::int32_t j, double limit) const;
  double relax_wall_time(std::int32_t i, const Wall& wall, double limit) const;
  Event relax_cell_crossing(std::int32_t i) const;
  /// Runs periodic action k at its time (synchronising first if it is a step).
  void fire_action(std::size_t k);
  /// Fixed particles: at rest, no spin, no force (after anything that may have set them).
  void hold_fixed_particles();
  /// The earliest next time of the synchronising actions (kNever if none), s.
  double next_synchronisation() const;

  void process_particle_event(std::int32_t i);
  /// Starts loading the records that processing particle i's event reads first (hints to the
  /// CPU; changes nothing). Always inlined: GCC deems a function of prefetches alone free of
  /// effects and deletes calls to it.
  [[gnu::always_inline]] void prefetch_particle(std::int32_t i) const {
    __builtin_prefetch(&agenda_[i]);
    __builtin_prefetch(&hot_[i]);
    __builtin_prefetch(&body_[i]);
    grid_.prefetch(i);
  }
  void collide_pair(std::int32_t i, std::int32_t j, double t);
  void collide_wall(std::int32_t i, std::int32_t w, double t);
  void cross_cell(std::int32_t i, int face);
  void advance(std::int32_t i, double t);
  ContactLaw effective_law(const ContactLaw& law, double normal_speed, double t, std::int32_t i,
                           std::int32_t j) const;
  /// Stall detector bookkeeping; partner_code is a particle index, or -1 - wall index.
  void book_collision(std::int32_t i, double t, std::int32_t partner_code);
  void check_pair_invariants(std::int32_t i, std::int32_t j, const Vec3& momentum_before) const;

  /// During a run the engine keeps each particle's changing state in two 64-byte records and a
  /// counter of its own, and the System's particle store is brought up to date (store_state)
  /// whenever anything outside may read it: when run_until returns, before an action, and
  /// around a synchronising step. An event then touches one cache line per record, where the
  /// store's arrays cost a cache miss each (a collision read ten of them per particle).
  ///
  /// Motion: what every prediction reads (the delayed state and the radius).
  using HotState = PairState;
  /// The rest of what a collision reads and changes.
  struct alignas(64) Body {
    Vec3 spin = Vec3::Zero();         ///< rad/s.
    double inverse_mass = 0;          ///< 1 / m_i, 1/kg.
    double inverse_inertia = 0;       ///< 1 / I_i, 1/(kg m^2).
    double last_collision = -kNever;  ///< Time of the last collision, s (TC model).
    std::uint32_t species = 0;        ///< Index into the species list.
    bool fixed = false;               ///< Of a fixed species: infinite mass in collisions.
  };
  /// Particle i's records from the particle store (at the start, and after a step).
  void load_records(std::int32_t i) {
    const ParticleStore& p = system_.particles;
    hot_[i] = HotState{p.position[i], p.clock[i], p.velocity[i], p.radius[i]};
    body_[i] = Body{p.spin[i],           1.0 / p.mass[i], 1.0 / p.inertia[i],
                    p.last_collision[i], p.species[i],    system_.species[p.species[i]].fixed};
    counter_[i] = p.event_counter[i];
  }
  /// Writes every particle's changing state from the records into `p`.
  void copy_state_to(ParticleStore& p) const;
  /// Brings the System's particle store up to date with the records.
  void store_state() { copy_state_to(system_.particles); }

  System system_;
  SimulatorOptions options_;
  std::vector<HotState> hot_;  ///< Per particle: its motion (see load_records).
  std::vector<Body> body_;     ///< Per particle: the rest of its changing state.
  /// Per particle: its event counter, bumped whenever its trajectory changes. Read for the
  /// partner of every prediction and every popped event, so kept in a compact array of its
  /// own (128 kB for 32000 particles: it stays in the L2 cache, where in the body records
  /// the read was a miss, 10 % of the run's time).
  std::vector<std::uint32_t> counter_;
  HierarchicalGrid grid_;
  Calendar calendar_;
  /// What one particle waits for, and its stall bookkeeping: read and written at each of its
  /// events, so kept in one cache line rather than four arrays (a cache miss each).
  struct alignas(64) Agenda {
    Event collision;                      ///< Earliest pair or wall collision.
    Event crossing;                       ///< Next cell crossing.
    double stall_window_start = -kNever;  ///< Start of the stall window, s.
    std::uint32_t stall_count = 0;        ///< Collisions in that window.
  };
  std::vector<Agenda> agenda_;           ///< Per particle.
  std::vector<PeriodicAction> actions_;  ///< Slot N + 1 + k: action k.
  std::size_t end_slot_ = 0;             ///< Slot N: the end of the current run_until.
  double time_ = 0;                      ///< Time of the last processed event, s.
  double last_particle_event_ = 0;       ///< Time of the last processed particle event, s.
  RunStatistics statistics_;
  bool has_gravity_ = false;
  bool relax_ = false;                         ///< options_.flight_model == Relax.
  std::vector<RelaxFlight> flights_;           ///< Relax: each particle's flight.
  double horizon_ = kNever;                    ///< Relax: no prediction reaches past this, s.
  bool restored_ = false;                      ///< Built from an EngineState (its events stand).
  double stall_window_ = 0;                    ///< s.
  std::vector<std::pair<std::string, double>> restored_action_times_;
  std::uint64_t events_without_progress_ = 0;  ///< Consecutive events at one time.
  const volatile std::sig_atomic_t* stop_flag_ = nullptr;
};

}  // namespace carom
