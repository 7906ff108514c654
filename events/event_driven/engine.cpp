#include "events/event_driven/engine.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "events/restored_actions.hpp"

namespace carom {

namespace {
/// Orders particles by their coarse cell so that neighbours sit close in memory.
std::vector<std::size_t> spatial_order(const System& system) {
  const ParticleStore& p = system.particles;
  HierarchicalGrid coarse(system.domain, {*std::max_element(p.radius.begin(), p.radius.end())});
  std::vector<std::int64_t> key(p.size());
  const auto& level = coarse.levels()[0];
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto c = coarse.cell_coordinates(0, p.position[i]);
    key[i] = c[0] + std::int64_t(level.cells[0]) * (c[1] + std::int64_t(level.cells[1]) * c[2]);
  }
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return key[a] < key[b]; });
  return order;
}

void validate_system(const System& system, FlightModel flight_model) {
  const std::size_t species = system.species.size();
  if (system.materials.species_count() != species || system.materials.wall_count() != system.walls.size())
    throw std::invalid_argument("the material table does not match the species and walls");
  for (std::size_t s = 0; s < species; ++s) {
    for (std::size_t t = s; t < species; ++t)
      system.materials.pair(s, t).validate("contact law " + system.species[s].name + "-" +
                                           system.species[t].name);
    for (std::size_t w = 0; w < system.walls.size(); ++w)
      system.materials.wall(s, w).validate("contact law " + system.species[s].name + "-wall " +
                                           system.walls[w].name);
  }
  for (std::uint32_t s : system.particles.species)
    if (s >= species) throw std::invalid_argument("a particle refers to a species that does not exist");
  const Vec3& g = system.flight.gravity;
  for (const Species& s : system.species)
    if (s.fixed && system.flight.has_gravity() && flight_model != FlightModel::Relax)
      throw std::invalid_argument("species '" + s.name +
                                  "' is fixed: under gravity that needs relax flights (each "
                                  "particle its own flight); ballistic flights share one gravity");
  validate_walls(system.walls, g, system.domain);
  validate_initial_state(system);
}
}  // namespace

EventDrivenEngine::EventDrivenEngine(System system, EventDrivenOptions options)
    : system_(std::move(system)),
      options_(options),
      threads_(options.threads > 0 ? options.threads : WorkerPool::default_threads()) {
  validate_system(system_, options_.flight_model);
  ParticleStore& p = system_.particles;
  const std::size_t n = p.size();
  if (n > 0) p.permute(spatial_order(system_));
  grid_ = HierarchicalGrid(system_.domain, p.radius, options_.grid_level_ratio, options_.grid_subdivision);
  for (std::size_t i = 0; i < n; ++i) grid_.insert(static_cast<std::int32_t>(i), p.position[i]);
  statistics_.resize(system_.species.size(), system_.walls.size());
  flight_kind_ = options_.flight_model == FlightModel::Relax ? Flights::Relax
                 : system_.flight.has_gravity()              ? Flights::Gravity
                                                             : Flights::Straight;
  flights_.assign(n, RelaxFlight{0.0, system_.flight.gravity});
  hold_fixed_particles();
  bound_flights();
  agenda_.assign(n, Agenda{});
  end_slot_ = n;
  calendar_.resize(n + 1);

  stall_.limit = options_.collapse.stall_collisions;
  stall_.window = options_.collapse.stall_window;
  if (stall_.window <= 0.0 && n > 0) {
    double mean_square = 0.0;
    for (const Vec3& v : p.velocity) mean_square += v.squaredNorm();
    stall_.window = StallDetector::default_window(
        options_.collapse, 2.0 * *std::min_element(p.radius.begin(), p.radius.end()),
        std::sqrt(mean_square / n), system_.flight.gravity.norm());
  }
  time_ = last_particle_event_ = n > 0 ? *std::max_element(p.clock.begin(), p.clock.end()) : 0.0;
  start_rate_monitor(time_);
  hot_.resize(n);
  body_.resize(n);
  counter_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) load_records(static_cast<std::int32_t>(i));
  reset_candidate_memos();
  reset_cell_speeds();
  // The stored states may have different clocks here: a particle need not be in its cell at
  // the latest of them, which the skipping of cells out of reach assumes (nothing skipped).
  level_speed2_.assign(grid_.levels().size(), kNever);
  for (std::size_t i = 0; i < n; ++i) predict_any(static_cast<std::int32_t>(i));
  reset_level_speeds();
}

void EventDrivenEngine::reset_level_speeds() {
  level_speed2_.assign(grid_.levels().size(), 0.0);
  for (std::size_t i = 0; i < hot_.size(); ++i) {
    double& bound = level_speed2_[grid_.level_of(static_cast<std::int32_t>(i))];
    bound = std::max(bound, hot_[i].velocity.squaredNorm());
  }
}

EventDrivenEngine::EventDrivenEngine(System system, EventDrivenOptions options, EngineState state)
    : system_(std::move(system)),
      options_(options),
      threads_(options.threads > 0 ? options.threads : WorkerPool::default_threads()) {
  system_.particles = std::move(state.particles);
  const std::size_t n = system_.particles.size();
  if (state.cells.size() != n || state.events.size() != n || state.stall_count.size() != n ||
      state.stall_window_start.size() != n || state.event_counters.size() != n ||
      state.last_collision.size() != n)
    throw std::invalid_argument("saved state: the arrays do not all hold one entry per particle");
  // A damaged checkpoint's species index would read past the species list, and counters sized
  // for other species or walls past their tables (found by fuzzing).
  for (std::size_t i = 0; i < n; ++i)
    if (system_.particles.species[i] >= system_.species.size())
      throw std::invalid_argument("saved state: particle " +
                                  std::to_string(system_.particles.id[i]) + " has species index " +
                                  std::to_string(system_.particles.species[i]) +
                                  ", but the scene has " + std::to_string(system_.species.size()) +
                                  " species: the checkpoint is damaged");
  // A damaged checkpoint's radius or state can be NaN or infinite, which the grid would turn
  // into cell indices out of range (found by fuzzing).
  for (std::size_t i = 0; i < n; ++i) {
    const ParticleStore& p = system_.particles;
    if (!(p.radius[i] > 0.0 && std::isfinite(p.radius[i])) || !p.position[i].allFinite() ||
        !p.velocity[i].allFinite() || !p.spin[i].allFinite() || !std::isfinite(p.clock[i]))
      throw std::invalid_argument("saved state: particle " + std::to_string(p.id[i]) +
                                  " has a radius that is not a positive finite number, or a "
                                  "position, velocity, spin or clock that is not finite (radius " +
                                  std::to_string(p.radius[i]) + " m): the checkpoint is damaged");
  }
  if (state.statistics.species_count != system_.species.size() ||
      state.statistics.wall_count != system_.walls.size())
    throw std::invalid_argument("saved state: the collision counters are for " +
                                std::to_string(state.statistics.species_count) + " species and " +
                                std::to_string(state.statistics.wall_count) +
                                " walls, the scene has " + std::to_string(system_.species.size()) +
                                " and " + std::to_string(system_.walls.size()));
  grid_ = HierarchicalGrid(system_.domain, system_.particles.radius, options_.grid_level_ratio,
                           options_.grid_subdivision);
  // Rebuild every cell's list in its saved order: each insertion goes first, so the last place first.
  std::vector<std::int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  if (state.places.size() == n)
    std::stable_sort(order.begin(), order.end(),
                     [&](auto a, auto b) { return state.places[a] > state.places[b]; });
  else if (!state.places.empty())
    throw std::invalid_argument("saved state: the cell-list places do not hold one entry per particle");
  for (std::int32_t i : order) {
    // A damaged checkpoint's cell would index outside the grid's lists (found by fuzzing).
    const std::array<int, 3>& cell = state.cells[i];
    const std::array<int, 3>& cells = grid_.levels()[grid_.level_of(i)].cells;
    for (int k = 0; k < 3; ++k)
      if (cell[k] < 0 || cell[k] >= cells[k])
        throw std::invalid_argument("saved state: particle " + std::to_string(system_.particles.id[i]) +
                                    "'s cell (" + std::to_string(cell[0]) + ", " + std::to_string(cell[1]) +
                                    ", " + std::to_string(cell[2]) + ") is outside its grid level of " +
                                    std::to_string(cells[0]) + " x " + std::to_string(cells[1]) + " x " +
                                    std::to_string(cells[2]) + " cells: the checkpoint is damaged");
    grid_.insert_at(i, cell);
  }
  flight_kind_ = options_.flight_model == FlightModel::Relax ? Flights::Relax
                 : system_.flight.has_gravity()              ? Flights::Gravity
                                                             : Flights::Straight;
  flights_ = std::move(state.flights);
  if (flights_.empty()) flights_.assign(n, RelaxFlight{0.0, system_.flight.gravity});
  if (flights_.size() != n) throw std::invalid_argument("saved state: flights missing");
  // The predictions bound every flight by the largest (bound_flights): a damaged flight must not
  // slip past them.
  for (std::size_t i = 0; i < n; ++i)
    if (!(flights_[i].rate >= 0.0 && std::isfinite(flights_[i].rate)) ||
        !flights_[i].drive.allFinite())
      throw std::invalid_argument("saved state: particle " +
                                  std::to_string(system_.particles.id[i]) +
                                  "'s flight has a drag rate that is not a finite number >= 0 or a "
                                  "drive that is not finite: the checkpoint is damaged");
  bound_flights();
  if (state.crossings.size() != n) throw std::invalid_argument("saved state: crossings missing");
  agenda_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    agenda_[i] = Agenda{state.events[i], state.crossings[i],
                        StallRecord{state.stall_window_start[i], state.stall_count[i]}};
  end_slot_ = n;
  calendar_.resize(n + 1);
  for (std::size_t i = 0; i < n; ++i) calendar_.set(i, next_event(i).time);
  time_ = state.time;
  last_particle_event_ = state.last_particle_event;
  statistics_ = std::move(state.statistics);
  gas_work_ = state.gas_work;
  flow_energy_ = state.flow_energy;
  stall_.limit = options_.collapse.stall_collisions;
  stall_.window = state.stall_window;
  start_rate_monitor(state.rate_start_time);
  if (state.rate_start_time >= 0.0) {
    rate_.start_pairs = state.rate_start_pairs;
    rate_.start_walls = state.rate_start_walls;
  } else {  // a checkpoint written before the monitor: its window starts now
    rate_.start_time = time_;
  }
  restored_action_times_ = std::move(state.action_times);
  restored_ = true;
  hot_.resize(n);
  body_.resize(n);
  counter_.assign(state.event_counters.begin(), state.event_counters.end());
  reset_candidate_memos();
  for (std::size_t i = 0; i < n; ++i) {
    body_[i].last_collision = state.last_collision[i];
    load_records(static_cast<std::int32_t>(i));
  }
  reset_cell_speeds();
  reset_level_speeds();
}

void EventDrivenEngine::start_rate_monitor(double t) {
  rate_.limit = options_.collapse.collision_frequency_limit();
  rate_.window = std::max<std::uint64_t>(10 * agenda_.size(), 1000);
  rate_.min_span = rate_.limit > 0.0 ? 5000.0 / rate_.limit : 0.0;
  rate_.start_pairs = statistics_.pair_events;
  rate_.start_walls = statistics_.wall_events;
  rate_.start_time = t;
}

void EventDrivenEngine::copy_state_to(ParticleStore& p) const {
  for (std::size_t i = 0; i < hot_.size(); ++i) {
    p.position[i] = hot_[i].position;
    p.velocity[i] = hot_[i].velocity;
    p.clock[i] = hot_[i].clock;
    p.spin[i] = body_[i].spin;
  }
}

EngineState EventDrivenEngine::state() const {
  EngineState s;
  s.particles = system_.particles;
  copy_state_to(s.particles);
  s.event_counters.assign(counter_.begin(), counter_.end());
  const std::size_t n = system_.particles.size();
  s.last_collision.resize(n);
  s.cells.resize(n);
  s.places.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.last_collision[i] = body_[i].last_collision;
    s.cells[i] = grid_.cell_of(static_cast<std::int32_t>(i));
    s.places[i] = grid_.place_in_cell(static_cast<std::int32_t>(i));
  }
  for (const Agenda& a : agenda_) {
    s.events.push_back(a.collision);
    s.crossings.push_back(a.crossing);
    s.stall_window_start.push_back(a.stall.window_start);
    s.stall_count.push_back(a.stall.count);
  }
  s.flights = flights_;
  s.time = time_;
  s.last_particle_event = last_particle_event_;
  s.statistics = statistics_;
  s.stall_window = stall_.window;
  s.gas_work = gas_work_;
  s.flow_energy = flow_energy_;
  s.rate_start_pairs = rate_.start_pairs;
  s.rate_start_walls = rate_.start_walls;
  s.rate_start_time = rate_.start_time;
  for (const PeriodicAction& a : actions_) s.action_times.emplace_back(a.name, a.next_time);
  return s;
}

void EventDrivenEngine::add_periodic_action(std::string name, double first_time, double interval,
                                            std::function<void()> action) {
  if (!(interval > 0.0)) throw std::invalid_argument(name + ": the interval must be positive");
  first_time = restored_next_time(restored_action_times_, name, first_time, time_, interval);
  actions_.push_back(PeriodicAction{std::move(name), first_time, interval, std::move(action), {}});
  calendar_.resize(end_slot_ + 1 + actions_.size());
  calendar_.set(end_slot_ + actions_.size(), first_time);
}

void EventDrivenEngine::add_synchronising_action(std::string name, double first_time, double interval,
                                                 std::function<void(GlobalStep&)> step) {
  if (!(interval > 0.0)) throw std::invalid_argument(name + ": the interval must be positive");
  if (!(first_time >= time_))
    throw std::invalid_argument(name + ": the first step is before the current time");
  first_time = restored_next_time(restored_action_times_, name, first_time, time_, interval);
  actions_.push_back(PeriodicAction{std::move(name), first_time, interval, {}, std::move(step)});
  calendar_.resize(end_slot_ + 1 + actions_.size());
  calendar_.set(end_slot_ + actions_.size(), first_time);
  const double horizon = next_synchronisation();
  if (horizon < horizon_ && flight_kind_ == Flights::Relax && !restored_) {
    // Predictions made so far may reach past the new horizon: make them again. (A restored
    // run's events were made with the saved horizon and stand as they are.)
    horizon_ = horizon;
    for (std::size_t i = 0; i < agenda_.size(); ++i) predict_any(static_cast<std::int32_t>(i));
  }
  horizon_ = horizon;
}

void EventDrivenEngine::hold_fixed_particles() {
  ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (system_.species[p.species[i]].fixed) {
      p.velocity[i] = p.spin[i] = Vec3::Zero();
      flights_[i] = RelaxFlight{};
    }
}

void EventDrivenEngine::reset_candidate_memos() {
  memo_.clear();
  // One grid level only: with several (fines among large spheres) most candidates come from the
  // other levels' scans, which the memo does not hold, and the fines 1:10 ran 0.95-0.97 times as
  // fast with memos (tests/bench/README.md, "The candidates remembered").
  if (!prefetching() || flight_kind_ == Flights::Relax || grid_.levels().size() > 1) return;
  memo_.resize(agenda_.size());
  for (CandidateMemo& m : memo_) m.reset();
}

void EventDrivenEngine::bound_flights() {
  flight_bounds_ = RelaxFlightBounds{};
  for (const RelaxFlight& f : flights_) flight_bounds_.include(f);
}

double EventDrivenEngine::next_synchronisation() const {
  double t = kNever;
  for (const PeriodicAction& a : actions_)
    if (a.step && a.next_time < t) t = a.next_time;
  return t;
}

SideThread* EventDrivenEngine::side_thread() {
  // Only relax predictions (exponentials, a root search: several microseconds each) are worth
  // handing over; a ballistic one (a quadratic per candidate) costs less than the hand-over
  // and the cache lines it moves (slower with it at N = 32000 and at 1e6: "The side thread" in
  // tests/bench/README.md; with predict_pair's trials, 2026-12-04, no faster in the main job's
  // settling). Below a few hundred particles other work takes most of an event.
  constexpr std::size_t kShared = 256;
  if (flight_kind_ != Flights::Relax || hot_.size() < kShared || threads_ == 1) return nullptr;
  if (!side_) side_ = std::make_shared<SideThread>();
  return side_.get();
}

void EventDrivenEngine::predict_any(std::int32_t i) {
  with_flight([&](auto flight) { predict<decltype(flight)>(i); });
}

template <class Flight>
void EventDrivenEngine::fire_action(std::size_t k) {
  PeriodicAction& action = actions_[k];
  time_ = action.next_time;
  pair_split_.interrupt();  // not a collision's work: left out of its timing
  if (!action.step) {
    store_state();
    action.action();
    action.next_time += action.interval;
    calendar_.set(end_slot_ + 1 + k, action.next_time);
    return;
  }
  // The step's loops share their work with the side thread, which has likely gone to sleep
  // during the events: woken now, it is spinning by the first of them.
  SideThread* side = side_thread();
  if (side != nullptr) side->wake();
  ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) advance<Flight>(static_cast<std::int32_t>(i), time_);
  last_particle_event_ = time_;
  store_state();
  // A synchronising action is the gas's hook (the fluid step, a drag kick): the kinetic energy
  // (and spin energy) it gives the particles is work done by the gas.
  const double kinetic_before = kinetic_energy(p);
  GlobalStep step{time_, p, flights_};
  step.side = side;
  action.step(step);
  if (flights_.size() != p.size() || hot_.size() != p.size())
    throw std::logic_error(action.name + " changed the number of particles or flights");
  hold_fixed_particles();
  gas_work_ += kinetic_energy(p) - kinetic_before;
  if (!step.change.empty()) apply_change(step.change);
  const std::size_t n = p.size();
  action.next_time += action.interval;
  calendar_.set(end_slot_ + 1 + k, action.next_time);
  horizon_ = next_synchronisation();
  for (std::size_t i = 0; i < n; ++i) {
    load_records(static_cast<std::int32_t>(i));
    ++counter_[i];
  }
  bound_flights();
  predict_all<Flight>();
}

bool EventDrivenEngine::run_until(double t_end) {
  if (!(t_end >= time_))
    throw std::invalid_argument("run_until: the end time " + std::to_string(t_end) +
                                " s is before the current time " + std::to_string(time_) + " s");
  if (flight_kind_ == Flights::Relax && horizon_ == kNever && !agenda_.empty())
    throw std::logic_error("relax flights need a synchronising action (the fluid step)");
  // The flight is chosen here, once: everything below is compiled for it.
  return with_flight([&](auto flight) { return run_events<decltype(flight)>(t_end); });
}

template <class Flight>
bool EventDrivenEngine::run_events(double t_end) {
  calendar_.set(end_slot_, t_end);
  pair_split_.interrupt();  // the caller's work since the last run (output) is not a collision's
  for (std::uint32_t countdown = 4096;; --countdown) {
    if (countdown == 0) {
      countdown = 4096;
      if (stop_flag_ != nullptr && *stop_flag_ != 0) {
        calendar_.set(end_slot_, kNever);
        store_state();
        return false;
      }
    }
    const std::size_t slot = calendar_.top_slot();
    // Large ballistic systems: this event's walks start loading before the calendar's update
    // (its sift waits on misses of its own), from the candidates its particle last walked.
    if (slot < end_slot_ && remembers_candidates<Flight>())
      prefetch_event(static_cast<std::int32_t>(slot));
    if (slot < end_slot_) {
      // Look ahead: with this particle's entry out of the way, the calendar's top is the next
      // event unless this one schedules an earlier one (5 times in 6 at phi = 0.4). Its
      // particle's records start loading now and arrive while this event is processed; they
      // were the first, exposed cache misses of every event. Every path of
      // process_particle_event sets the slot again.
      calendar_.set(slot, kNever);
      const std::size_t next = calendar_.top_slot();
      if (next < end_slot_) {
        prefetch_particle(static_cast<std::int32_t>(next));
        if (prefetching()) calendar_.prefetch(next);
        if (remembers_candidates<Flight>()) __builtin_prefetch(&memo_[next]);
      }
      try {
        process_particle_event<Flight>(static_cast<std::int32_t>(slot));
      } catch (...) {  // the stall detector: leave the calendar and the store consistent
        calendar_.set(slot, next_event(static_cast<std::int32_t>(slot)).time);
        store_state();
        throw;
      }
    } else if (slot == end_slot_) {
      calendar_.set(end_slot_, kNever);
      time_ = t_end;
      store_state();
      return true;
    } else {
      fire_action<Flight>(slot - end_slot_ - 1);
    }
  }
}

Vec3 EventDrivenEngine::position(std::size_t i) const {
  const HotState& m = hot_[i];
  return with_flight([&](auto flight) {
    return decltype(flight)::position_after(m, time_ - m.clock, system_.flight, flights_[i]);
  });
}

Vec3 EventDrivenEngine::velocity(std::size_t i) const {
  const HotState& m = hot_[i];
  return with_flight([&](auto flight) {
    return decltype(flight)::velocity_after(m, time_ - m.clock, system_.flight, flights_[i]);
  });
}

double EventDrivenEngine::kinetic_energy(const ParticleStore& p) {
  double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    sum += 0.5 * (p.mass[i] * p.velocity[i].squaredNorm() + p.inertia[i] * p.spin[i].squaredNorm());
  return sum;
}

Energies EventDrivenEngine::energies() const {
  Energies e;
  const ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e.translational += 0.5 * p.mass[i] * velocity(i).squaredNorm();
    e.rotational += 0.5 * p.inertia[i] * body_[i].spin.squaredNorm();
    e.potential -= p.mass[i] * system_.flight.gravity.dot(position(i));
  }
  e.dissipated = statistics_.dissipated_energy;
  e.gas_work = gas_work_;
  e.flow = flow_energy_;
  // The gas's work on each relax flight from the particle's clock to now, not yet booked.
  with_flight([&](auto flight) {
    using Flight = decltype(flight);
    if constexpr (Flight::kGasForces)
      for (std::size_t i = 0; i < p.size(); ++i) {
        HotState m = hot_[i];
        e.gas_work += body_[i].mass * Flight::move_booking_gas_work(m, time_ - m.clock, system_.flight,
                                                                    flights_[i]);
      }
  });
  return e;
}

std::string EventDrivenEngine::describe(std::int32_t i) const {
  const ParticleStore& p = system_.particles;
  std::ostringstream out;
  out << "particle " << p.id[i] << " (species " << system_.species[p.species[i]].name << ", at "
      << position(i).transpose() << " m)";
  return out.str();
}

template <class Flight>
void EventDrivenEngine::process_particle_event(std::int32_t i) {
  const Event event = next_event(i);
  // Stall detector, second half: events that never move time on (the first half, in
  // book_collision, counts one particle's collisions in a short window).
  if (stall_.stuck(event.time, last_particle_event_, agenda_.size()))
    throw InelasticCollapse(
        stuck_diagnostic(event.time, stall_.events_without_progress, describe(i), options_.collapse),
                            {system_.particles.id[i]});
  switch (event.kind) {
    case EventKind::Pair:
      // (With candidate memos, prefetch_event started these before the calendar's update.)
      if (prefetching() && !remembers_candidates<Flight>()) prefetch_pair(i, event.partner);
      if (counter_[event.partner] != event.partner_counter) {
        ++statistics_.invalid_events;
        predict<Flight>(i, /*new_trajectory=*/false);
        return;
      }
      collide_pair<Flight>(i, event.partner, event.time);
      break;
    case EventKind::Wall:
      collide_wall<Flight>(i, event.partner, event.time);
      break;
    case EventKind::CellCrossing:
      last_particle_event_ = time_ = event.time;
      cross_cell<Flight>(i, event.partner);
      break;
    case EventKind::None:
      // Only reachable if a particle has nothing to do and the run has no end: wait.
      calendar_.set(i, kNever);
      return;
  }
  ++statistics_.events;
}

template bool EventDrivenEngine::run_events<StraightFlights>(double);
template bool EventDrivenEngine::run_events<GravityFlights>(double);
template bool EventDrivenEngine::run_events<RelaxFlights>(double);

}  // namespace carom
