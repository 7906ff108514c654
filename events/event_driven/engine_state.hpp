#pragma once
/// The complete dynamic state of an event-driven run, and its HDF5 form (checkpoints).
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/hdf5.hpp"
#include "core/particles.hpp"
#include "core/relax_flight.hpp"
#include "events/event_driven/event.hpp"
#include "events/statistics.hpp"

namespace carom {

/// Everything needed to continue a run exactly (bit for bit) from where it stopped: the
/// particles' stored (delayed) states, their grid cells, the calendar's particle entries, the
/// counters and the clocks. The System's other parts (box, walls, species, laws) come from the
/// scene again.
struct EngineState {
  ParticleStore particles;                          ///< In the engine's internal order.
  std::vector<std::uint32_t> event_counters;        ///< Each particle's event counter.
  std::vector<double> last_collision;               ///< Each particle's last collision time, s.
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
  double gas_work = 0;                              ///< Gas work booked so far, J.
  double flow_energy = 0;  ///< Energy brought in by flow minus taken out, J.
  std::uint64_t rate_start_pairs = 0;               ///< Lasting-contact window: pair count,
  std::uint64_t rate_start_walls = 0;               ///< wall count,
  double rate_start_time = -1;                      ///< and start, s (< 0: not saved).
  std::vector<std::pair<std::string, double>> action_times;  ///< Next time of each action, s.
};

/// Writes `state` into `group`. Layout (doubles as native doubles: bit for bit): attributes
/// method = "event_driven", time, last_particle_event, stall_window, gas_work,
/// flow_energy, rate_start_pairs, rate_start_walls, rate_start_time; particles/ (position,
/// velocity, spin (N x 3), clock, radius, mass, inertia, species, id, and the engine's
/// event_counter and last_collision), cells (N x 3), cell_list_places, events/ and crossings/
/// (each: time, partner, partner_counter, kind), flights/ (rate, drive (N x 3)), statistics/
/// (counters as attributes; pair_collisions, pair_impulse, wall_collisions, wall_impulse (W x 3),
/// virial (3 x 3)), stall_window_start, stall_count, actions/ (name, next_time).
void write_engine_state(const h5::Group& group, const EngineState& state);
/// Reads what write_engine_state wrote (checkpoints of earlier versions without the method
/// attribute or the cell-list places included). Throws std::runtime_error naming the file, the
/// object and what is missing or wrong.
EngineState read_engine_state(const h5::Group& group);

}  // namespace carom
