#pragma once
/// The event-driven hard-sphere engine: exact flights and binary collisions from event to event
/// (core/DESIGN.md, "Particles and flights", "Events and the calendar", "Collision laws and
/// collapse"), the first CollisionMethod.
///
/// Its pieces, one file each:
///   engine.cpp                 construction, global events (actions), the loop, the state
///   flights.hpp                the three flights (straight, gravity, relax) as types
///   ballistic_predictions.cpp  predictions for straight and gravity flights
///   relax_predictions.cpp      predictions for relax flights
///   collisions.cpp             pair and wall collisions, cell crossings, invariant checks
///   stall_detector.*           the collapse detector
///   engine_state*              the saved state and its HDF5 form
///   flow_change.cpp            particles leaving and entering (inflow, outflow)
///   calendar.hpp, event.hpp, pair_batch.*  the event calendar, the event record, batched tests
///   candidate_memo.hpp         large systems: each particle's last candidates, as loading hints
/// The collision laws are in events/laws/, shared with the other methods.
#include <csignal>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "core/cell_grid.hpp"
#include "core/flight_model.hpp"
#include "core/huge_pages.hpp"
#include "core/relax_flight.hpp"
#include "core/side_thread.hpp"
#include "core/split_chooser.hpp"
#include "core/system.hpp"
#include "core/worker_pool.hpp"
#include "events/event_driven/calendar.hpp"
#include "events/event_driven/candidate_memo.hpp"
#include "events/event_driven/engine_state.hpp"
#include "events/event_driven/event.hpp"
#include "events/event_driven/flights.hpp"
#include "events/event_driven/options.hpp"
#include "events/event_driven/pair_batch.hpp"
#include "events/event_driven/stall_detector.hpp"
#include "events/laws/collapse.hpp"
#include "events/method.hpp"
#include "events/statistics.hpp"

namespace carom {

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

class EventDrivenEngine final : public CollisionMethod {
 public:
  /// Takes the system, validates the initial state (throws std::invalid_argument), builds the
  /// grid and predicts every particle's first event.
  explicit EventDrivenEngine(System system, EventDrivenOptions options = {});

  /// Continues a saved run: `system` supplies box, walls, species and laws (its particles are
  /// ignored), `state` everything that moves. Actions added later under a saved name resume at
  /// their saved next time.
  EventDrivenEngine(System system, EventDrivenOptions options, EngineState state);

  std::string_view kind() const override { return "event_driven"; }

  /// A copy of the complete dynamic state (see EngineState).
  EngineState state() const;
  void save_state(const h5::Group& group) const override { write_engine_state(group, state()); }

  /// Processes every event up to time t_end (s) and stops there. Returns true when it got
  /// there, false when the stop flag (see set_stop_flag) was raised first: then the run stands
  /// at its last processed event, in a consistent state that can be checkpointed and resumed.
  /// Throws InelasticCollapse when the stall detector fires.
  bool run_until(double t_end) override;

  /// A flag (set by a signal handler, say) that run_until checks every few thousand events.
  void set_stop_flag(const volatile std::sig_atomic_t* flag) override { stop_flag_ = flag; }

  /// Registers an action to run at first_time and then every interval seconds (a global event).
  void add_periodic_action(std::string name, double first_time, double interval,
                           std::function<void()> action) override;

  /// Registers a synchronising action (see PeriodicAction::step): the fluid step, drag kicks.
  /// With FlightModel::Relax, predictions never reach past the next one, so a Relax run needs
  /// at least one.
  void add_synchronising_action(std::string name, double first_time, double interval,
                                std::function<void(GlobalStep&)> step) override;

  /// Each particle's current flight (FlightModel::Relax), in the engine's order.
  const std::vector<RelaxFlight>& flights() const { return flights_; }
  /// The candidates particle i's last ballistic prediction walked, kept as loading hints in
  /// large systems of one grid level (candidate_memo.hpp); nullptr where none are kept.
  const CandidateMemo* candidate_memo(std::size_t i) const {
    return memo_.empty() ? nullptr : &memo_[i];
  }

  /// The current time, s.
  double time() const override { return time_; }
  /// Box, walls, species, laws and particles. The particle store is up to date (each state as
  /// of its particle's clock) whenever run_until is not running, and inside actions; read the
  /// state at the current time through position(i), velocity(i) and spin(i).
  const System& system() const override { return system_; }
  const EventDrivenOptions& options() const { return options_; }
  const RunStatistics& statistics() const override { return statistics_; }
  /// Predictions made on the side thread so far (predict_pair; changes no result): for tests
  /// and diagnostics.
  unsigned long long side_predictions() const { return side_ ? side_->side_runs() : 0; }
  const HierarchicalGrid& grid() const { return grid_; }

  /// Particle i's position at the current time, m (its stored state is not changed).
  Vec3 position(std::size_t i) const override;
  /// Particle i's velocity at the current time, m/s.
  Vec3 velocity(std::size_t i) const override;
  /// Particle i's spin, rad/s.
  Vec3 spin(std::size_t i) const override { return body_[i].spin; }
  Energies energies() const override;

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
  /// Which of the flights of flights.hpp this run's particles fly (chosen at construction).
  enum class Flights { Straight, Gravity, Relax };
  /// Calls visit(Flight{}) with this run's flight type: the one place that turns flight_kind_
  /// into a type.
  template <class Visit>
  decltype(auto) with_flight(Visit&& visit) const {
    switch (flight_kind_) {
      case Flights::Straight: return visit(StraightFlights{});
      case Flights::Gravity: return visit(GravityFlights{});
      case Flights::Relax: break;
    }
    return visit(RelaxFlights{});
  }

  // --- The loop, templated over the flight (engine.cpp, collisions.cpp) -----------------------
  template <class Flight>
  bool run_events(double t_end);
  template <class Flight>
  void process_particle_event(std::int32_t i);
  template <class Flight>
  void fire_action(std::size_t k);
  template <class Flight>
  void collide_pair(std::int32_t i, std::int32_t j, double t);
  template <class Flight>
  void collide_wall(std::int32_t i, std::int32_t w, double t);
  template <class Flight>
  void cross_cell(std::int32_t i, int face);
  /// Moves particle i's stored state on to time t (s).
  template <class Flight>
  void advance(std::int32_t i, double t) {
    HotState& m = hot_[i];
    const double dt = t - m.clock;
    if (dt == 0.0) return;
    if constexpr (Flight::kGasForces)
      gas_work_ += body_[i].mass * Flight::move_booking_gas_work(m, dt, system_.flight, flights_[i]);
    else
      Flight::move(m, dt, system_.flight, flights_[i]);
    m.clock = t;
  }
  /// The worker threads for a loop over every particle, or null to run it on this thread
  /// (one thread asked for, or too few particles to be worth waking the workers).
  WorkerPool* shared_workers();
  /// The second thread of a relax run (a collision's two predictions, the predictions after a
  /// fluid step and the gas step's parts, each shared with it), or null (other flights, one
  /// thread asked for, or too few particles: see side_thread's definition).
  SideThread* side_thread();
  /// Predicts all of particle i's events for the flights of this run.
  void predict_any(std::int32_t i);
  /// Removes and adds particles (a flow step; every particle is synchronised at time_ and the
  /// store is up to date): the store, the records, the grid and the calendar are rebuilt for
  /// the new particles (flow_change.cpp); the caller then predicts every particle's events.
  void apply_change(const ParticleChange& change);

  // --- The prediction interface: one implementation per flight --------------------------------
  /// Predicts particle i's next collision, and its next cell crossing when its trajectory is
  /// new (a particle whose predicted partner moved away keeps its crossing), into its agenda.
  /// Reads the records, the grid and the counters and writes agenda_[i] only: the plans of two
  /// particles may be made at once.
  template <class Flight>
  void plan(std::int32_t i, bool new_trajectory = true);
  /// plan, then schedule.
  template <class Flight>
  void predict(std::int32_t i, bool new_trajectory = true) {
    plan<Flight>(i, new_trajectory);
    schedule(i);
  }
  /// Predicts and schedules both partners of a collision, scheduled in the order i, j: the two
  /// plans at once when a side thread is there (side_thread) and pair_split_ finds that faster
  /// on this machine, else one after the other.
  template <class Flight>
  void predict_pair(std::int32_t i, std::int32_t j) {
    auto one_after_other = [&] {
      plan<Flight>(i);
      schedule(i);
      plan<Flight>(j);
    };
    if (SideThread* side = side_thread()) {
      pair_split_.run(
          [&] {
            side->run_beside([&] { plan<Flight>(j); },
                             [&] {
                               plan<Flight>(i);
                               schedule(i);  // the calendar: this thread only
                             });
          },
          one_after_other);
    } else {
      one_after_other();
    }
    schedule(j);
  }
  /// After particle i crossed a cell face on `axis` in `direction` (same trajectory): its next
  /// crossing, and partners in the cells that just came into reach; schedules it.
  template <class Flight>
  void predict_after_crossing(std::int32_t i, int axis, int direction);

  // Ballistic flights (ballistic_predictions.cpp).
  /// Particle i's earliest wall or pair collision, into its agenda.
  template <bool kGravity>
  void plan_ballistic(std::int32_t i);
  template <bool kGravity>
  void scan_slab(std::int32_t i, int axis, int direction);
  double wall_time(std::int32_t i, const Wall& wall) const;
  Event cell_crossing(std::int32_t i) const;
  /// cell_crossing without gravity (straight flights), bit for bit the same event.
  Event straight_cell_crossing(std::int32_t i) const;
  /// Earliest contact of i with the particles of the given cells of `level`, if earlier than
  /// best_time (updated); returns the partner or -1.
  template <bool kGravity>
  std::int32_t scan_cells(std::int32_t i, int level, const std::int32_t* cells, int count,
                          bool wrapped, double& best_time, CandidateMemo* memo = nullptr) const;
  /// Earliest contact of i with the particles of the levels other than its own, in the cells
  /// that cover its cell (after a crossing along (axis, direction) with direction != 0: only
  /// those that just came into reach), if earlier than `best` (updated).
  /// Where a level is much finer than i's (walks_far_into), a full prediction of a straight
  /// flight walks only its cells that can hold a contact before `best` (scan_finer_level_near,
  /// with options_.skip_unreachable_cells); the earliest contact is the same bit for bit.
  template <bool kGravity>
  void scan_other_levels(std::int32_t i, Event& best, int axis = 0, int direction = 0) const;
  /// Whether a particle of level `own` walks the cells of `level` with scan_finer_level_near:
  /// a finer level whose cells are many along each axis of the block that covers one of own's.
  bool walks_far_into(int own, int level) const;
  /// Hands `scan` the cells of the finer `level` that cover i's cell and can hold a particle
  /// that touches i before best.time, which `scan` lowers as it finds partners: those within
  /// touching distance of i first, then the rest in order.
  template <class Scan>
  void scan_finer_level_near(std::int32_t i, int level, const Event& best, Scan&& scan) const;

  // Relax flights (relax_predictions.cpp).
  /// What relax_pair_time reads of particle i's stored state for every partner: |v| (m/s) and
  /// |a(v)| (m/s^2), computed once per prediction.
  struct RelaxMotion {
    double speed, acceleration;
    static RelaxMotion of(const PairState& state, const RelaxFlight& flight) {
      return {state.velocity.norm(), flight.acceleration(state.velocity).norm()};
    }
  };
  /// Contact time of i and j if before `limit` (and the horizon), else kNever; s. motion_i is
  /// RelaxMotion::of i's record and flight.
  double relax_pair_time(std::int32_t i, std::int32_t j, double limit,
                         const RelaxMotion& motion_i) const;
  double relax_wall_time(std::int32_t i, const Wall& wall, double limit) const;
  Event relax_cell_crossing(std::int32_t i) const;
  /// Particle i's earliest wall or pair collision before `limit` (its next crossing), or none.
  /// Reads the records, the grid and the counters only: safe to call for many particles at once.
  Event relax_collision(std::int32_t i, double limit) const;
  /// drop_cells_out_of_reach (reach_cells.hpp) for i's own-level block `cells` (count of
  /// them, `wrapped` as own_block tells); debug builds check every dropped cell's particles
  /// against may_reach.
  int drop_unreachable_cells(std::int32_t i, const ReachQuery& query, std::int32_t* cells,
                             int count, bool wrapped) const;
  /// Relax: sets each grid cell's bound (HierarchicalGrid::raise_cell_bound) to the largest
  /// speed (RelaxFlightBounds::speed_bound) of its particles' stored velocities, and
  /// speed_clock_ to the earliest clock. The bounds then stay valid as long as every particle
  /// whose stored velocity changes or that enters a cell raises its cell's (note_speed,
  /// note_cell_entered).
  void reset_cell_speeds();
  /// Raises the speed bound of particle i's cell to i's stored speed (relax flights: the
  /// bounds serve relax predictions), or the square of its level's to i's squared speed
  /// (straight flights: for scan_other_levels).
  template <class Flight>
  void note_speed(std::int32_t i) {
    note_cell_entered<Flight>(i);
    if constexpr (std::is_same_v<Flight, StraightFlights>) {
      double& bound = level_speed2_[grid_.level_of(i)];
      bound = std::max(bound, hot_[i].velocity.squaredNorm());
    }
  }
  /// What note_speed does for a particle that entered a cell with the same velocity: raises
  /// that cell's bound (relax flights; a level's bound does not change).
  template <class Flight>
  void note_cell_entered(std::int32_t i) {
    if constexpr (std::is_same_v<Flight, RelaxFlights>)
      grid_.raise_cell_bound(i, RelaxFlightBounds::speed_bound(hot_[i].velocity));
  }
  /// Sets each level's squared speed bound (level_speed2_) to the largest squared speed of its
  /// particles' stored velocities. It then stays valid as long as every straight flight whose
  /// velocity changes raises it (note_speed).
  void reset_level_speeds();
  /// After a synchronising action: every particle's events predicted again (relax flights:
  /// planned in pieces taken in turn by this and the side thread, or on the worker threads
  /// from 3 threads on, scheduled in particle order; else one by one).
  template <class Flight>
  void predict_all();

  /// Sets flight_bounds_ from flights_ (after anything that changed a flight).
  void bound_flights();
  /// Puts particle i's earlier event (collision or crossing) in the calendar.
  void schedule(std::int32_t i);
  /// The time schedule(i) gives particle i's slot (its agenda's times held at or after the last
  /// particle event).
  double scheduled_time(std::int32_t i);
  /// Sets the lasting-contact monitor's limit and window from the options and starts its
  /// window at time t (s) with the current counts.
  void start_rate_monitor(double t);
  /// sum (m v^2 + I w^2) / 2 of the stored velocities and spins, J.
  static double kinetic_energy(const ParticleStore& p);
  /// Fixed particles: at rest, no spin, no force (after anything that may have set them).
  void hold_fixed_particles();
  /// The earliest next time of the synchronising actions (kNever if none), s.
  double next_synchronisation() const;

  /// Starts loading the records that processing particle i's event reads first (hints to the
  /// CPU; changes nothing). Always inlined: GCC deems a function of prefetches alone free of
  /// effects and deletes calls to it.
  [[gnu::always_inline]] void prefetch_particle(std::int32_t i) const {
    __builtin_prefetch(&agenda_[i]);
    __builtin_prefetch(&hot_[i]);
    __builtin_prefetch(&body_[i]);
    grid_.prefetch(i);
  }
  /// Whether the system is large enough for the loading hints (options_.prefetch_from): its
  /// records (about 190 bytes a particle) outgrow the last-level cache, and the hints pay.
  bool prefetching() const { return agenda_.size() >= options_.prefetch_from; }
  /// For a collision of i with j in a large system: starts loading what the collision and the
  /// two predictions read late, each load otherwise waiting on the one before (j's records and
  /// place, the first particles of the cells of i's block). i's records were prefetched one
  /// event ahead.
  [[gnu::always_inline]] void prefetch_pair(std::int32_t i, std::int32_t j) const {
    prefetch_particle(j);
    calendar_.prefetch(static_cast<std::size_t>(j));
    grid_.prefetch_own_block(i);
  }
  /// Whether the predictions of Flight keep each particle's candidates (candidate_memo.hpp):
  /// the ballistic ones in large systems (relax predictions walk their own way).
  template <class Flight>
  bool remembers_candidates() const {
    return !Flight::kGasForces && !memo_.empty();
  }
  /// Sizes the candidate memos for the particles present (prefetching(), ballistic flights and
  /// one grid level only), each reset.
  void reset_candidate_memos();
  /// For particle i's event, at the top of the calendar in a large ballistic system: starts
  /// loading what its predictions walk before the calendar is updated: its remembered
  /// candidates and its cells' first particles, and for a pair event what prefetch_pair starts
  /// and the partner's memo. i's own records and place were hinted one event ahead. A cell
  /// crossing's prediction walks the cells that come into reach, not the block: their first
  /// particles are hinted instead.
  [[gnu::always_inline]] void prefetch_event(std::int32_t i) const {
    const Event e = next_event(static_cast<std::size_t>(i));
    if (e.kind == EventKind::CellCrossing) {
      grid_.prefetch_entering_slab(i, e.partner);
      return;
    }
    memo_[i].hint(i, hot_.data(), grid_.next_array(), counter_.data());
    if (e.kind == EventKind::Pair) {
      prefetch_pair(i, e.partner);
      __builtin_prefetch(&memo_[e.partner]);
    } else {
      grid_.prefetch_own_block(i);
    }
  }
  /// Stall detector bookkeeping; partner_code is a particle index, or -1 - wall index.
  void book_collision(std::int32_t i, double t, std::int32_t partner_code);
  /// "particle ID (species NAME, at X Y Z m)", for diagnostics.
  std::string describe(std::int32_t i) const;
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
    double mass = 0;                  ///< m_i, kg (books the gas work of relax flights).
    std::uint32_t species = 0;        ///< Index into the species list.
    bool fixed = false;               ///< Of a fixed species: infinite mass in collisions.
  };
  static_assert(sizeof(Body) == 64, "one cache line");
  /// Particle i's motion and body from the particle store (at the start, and after a step);
  /// its last collision time is kept as it is.
  void load_records(std::int32_t i) {
    const ParticleStore& p = system_.particles;
    hot_[i] = HotState{p.position[i], p.clock[i], p.velocity[i], p.radius[i]};
    const double last = body_[i].last_collision;
    body_[i] = Body{p.spin[i], 1.0 / p.mass[i], 1.0 / p.inertia[i], last, p.mass[i], p.species[i],
                    system_.species[p.species[i]].fixed};
  }
  /// Writes every particle's changing state from the records into `p`.
  void copy_state_to(ParticleStore& p) const;
  /// Brings the System's particle store up to date with the records.
  void store_state() { copy_state_to(system_.particles); }

  System system_;
  EventDrivenOptions options_;
  Flights flight_kind_ = Flights::Straight;
  BigVector<HotState> hot_;  ///< Per particle: its motion (see load_records).
  BigVector<Body> body_;     ///< Per particle: the rest of its changing state.
  /// Per particle: its event counter, bumped whenever its trajectory changes. Read for the
  /// partner of every prediction and every popped event, so kept in a compact array of its
  /// own (128 kB for 32000 particles: it stays in the L2 cache, where in the body records
  /// the read was a miss, 10 % of the run's time).
  BigVector<std::uint32_t> counter_;
  HierarchicalGrid grid_;
  Calendar calendar_;
  /// What one particle waits for, and its stall bookkeeping: read and written at each of its
  /// events, so kept in one cache line rather than four arrays (a cache miss each).
  struct alignas(64) Agenda {
    Event collision;  ///< Earliest pair or wall collision.
    Event crossing;   ///< Next cell crossing.
    StallRecord stall;
  };
  BigVector<Agenda> agenda_;             ///< Per particle.
  /// Per particle, in large systems only (prefetching()): its last candidates, as hints.
  BigVector<CandidateMemo> memo_;
  std::vector<PeriodicAction> actions_;  ///< Slot N + 1 + k: action k.
  std::size_t end_slot_ = 0;             ///< Slot N: the end of the current run_until.
  double time_ = 0;                      ///< Time of the last processed event, s.
  double last_particle_event_ = 0;       ///< Time of the last processed particle event, s.
  RunStatistics statistics_;
  TaggedImpulses& tagged_impulses() override { return statistics_.tagged; }
  StallDetector stall_;
  RateMonitor rate_;
  std::vector<RelaxFlight> flights_;           ///< Relax: each particle's flight.
  /// Relax: bounds on every flight in flights_ (set by bound_flights whenever they change).
  RelaxFlightBounds flight_bounds_;
  /// Relax: the levels (bit l for level l) whose cells hold several particles each where the
  /// particles are (HierarchicalGrid::list_length_seen above kLongLists), measured at every
  /// kListsEvery-th fluid step: their predictions walk deeper into each list without a branch.
  std::uint32_t long_lists_ = 0;
  /// Relax: predict_all calls so far (when the list lengths are measured again; speed only).
  std::uint64_t lists_measured_ = 0;
  /// Relax: no stored clock is earlier than this (set with the cells' speed bounds by
  /// reset_cell_speeds), s.
  double speed_clock_ = 0;
  /// Per grid level, at or above the squared speed of each of its particles, (m/s)^2; infinite
  /// (nothing skipped) until reset_level_speeds. Read by the straight flights' predictions that
  /// skip the finer levels' cells out of reach (scan_other_levels).
  std::vector<double> level_speed2_;
  /// Work done on the particles by the gas since the start, J: by the gas forces of relax
  /// flights up to each particle's clock, and by the synchronising actions (drag kicks).
  double gas_work_ = 0;
  /// Energy that entering particles brought minus what leaving ones took out, J.
  double flow_energy_ = 0;
  double horizon_ = kNever;                    ///< Relax: no prediction reaches past this, s.
  /// Threads for predict_all (made at the first synchronising action that has enough
  /// particles to share; shared by copies of the engine, which use it one at a time).
  std::shared_ptr<WorkerPool> workers_;
  /// The side thread of predict_pair (made at the first collision of a run with enough
  /// particles and threads; shared by copies of the engine, which use it one at a time).
  std::shared_ptr<SideThread> side_;
  /// Whether predict_pair's two plans go faster split with side_ or one after the other here
  /// (measured as the run goes: see core/split_chooser.hpp).
  SplitChooser<> pair_split_;
  int threads_ = 1;  ///< options_.threads, or the default it stands for (resolved at construction).
  bool restored_ = false;                      ///< Built from an EngineState (its events stand).
  std::vector<std::pair<std::string, double>> restored_action_times_;
  const volatile std::sig_atomic_t* stop_flag_ = nullptr;
};

// The prediction interface's implementations (ballistic_predictions.cpp, relax_predictions.cpp).
template <>
void EventDrivenEngine::plan<StraightFlights>(std::int32_t i, bool new_trajectory);
template <>
void EventDrivenEngine::plan<GravityFlights>(std::int32_t i, bool new_trajectory);
template <>
void EventDrivenEngine::plan<RelaxFlights>(std::int32_t i, bool new_trajectory);
template <>
void EventDrivenEngine::predict_all<RelaxFlights>();

template <class Flight>
void EventDrivenEngine::predict_all() {
  reset_level_speeds();
  for (std::size_t i = 0; i < hot_.size(); ++i) predict<Flight>(static_cast<std::int32_t>(i));
}

template <>
void EventDrivenEngine::predict_after_crossing<StraightFlights>(std::int32_t i, int axis, int direction);
template <>
void EventDrivenEngine::predict_after_crossing<GravityFlights>(std::int32_t i, int axis, int direction);
template <>
void EventDrivenEngine::predict_after_crossing<RelaxFlights>(std::int32_t i, int axis, int direction);

}  // namespace carom
