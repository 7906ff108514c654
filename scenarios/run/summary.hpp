#pragma once
/// summary.json: what a run (or one resumed stretch of it) did, in numbers a user reads first.
///
/// Everything rate-like or averaged refers to the stretch of simulated time this process ran,
/// [start_time, end_time] (from 0 for `carom run`, from the checkpoint for `carom resume`);
/// counts are given for that stretch and in total since t = 0. Keys:
///   run                      the run's identity, as in run.h5 and checkpoint.h5: {id (hex),
///                            scene_hash (hex), seed, method}
///   status                   "completed" | "interrupted" | "inelastic_collapse" | "failed" (an
///                            output could not be written) | "stalled" (simulated time stopped
///                            advancing, run.cpp's StallWatch) | a method's own failure
///   message                  why it stopped, when not "completed"
///   start_time, end_time     s
///   wall_seconds             wall-clock time of this process's run loop, s
///   particles, events, collisions, events_total, collisions_total
///   events_per_second, collisions_per_second     per wall-clock second
///   collision_rate_per_particle   {"a-b": collisions per unit time of one particle of species a
///                             with particles of species b, 1/s; with inflow or outflow, per
///                             particle present: the count over the time integral of the
///                             number of particles of a present}
///   enskog_rate_per_particle      the same from Enskog at the time-averaged temperature
///                             (periodic, gravity-free scenes without extra walls; else null)
///   impact_speed             normal approach speed above which a collision is an impact, m/s
///                            (scenarios/scene/impact_speed.hpp)
///   impact_rate_per_particle like collision_rate_per_particle, impacts only
///   wall_collisions          {"species@wall": count in the stretch}
///   wall_impacts             {"species@wall": impacts in the stretch}
///   wall_force               {"wall": time-averaged force of the particles on it, N}
///   mean_temperature         time-averaged granular temperature (2/3) E_kin / N, J
///   pressure                 time-averaged {kinetic, collisional, total}, Pa:
///                            P_kin = <2 E_kin / (3 V)>, P_coll = sum r_ij . J_i / (3 V dt)
///   energy                   final {translational, rotational, potential, dissipated}, J
///   simulated_seconds_per_wall_second
///   gas                      runs with a gas: {fluid_steps, unconverged_steps (SIMPLE stopped at
///                            its iteration limit), mapping_seconds, solve_seconds,
///                            interpolation_seconds (wall time of each part of the fluid steps),
///                            event_seconds (the rest of the wall time: the particles' events)}
///   flow                     runs with inflow or outflow (flow_run.hpp): each inflow's set and
///                            measured mass flow, each outflow's, mean particles present
///   analysis                 the run's analysis from t = 0 (run_analysis.hpp): mixing {rate,
///                            time_to_m08, ...}, dispersion, collision_frequency (measured,
///                            per particle, whole run), kinetic_theory_frequency,
///                            granular_temperature, segregation_index, mechanism
#include <chrono>
#include <string>

#include "events/method.hpp"
#include "fluid/coupling.hpp"
#include "scenarios/run/flow_run.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

/// A JSON string literal (quotes and control characters escaped).
std::string json_string(const std::string& text);
/// A JSON number, shortest exact form; null for NaN and infinities.
std::string json_number(double x);

/// Time integrals, by the trapezoid rule over the instants the run loop samples.
class TimeAverages {
 public:
  /// Records the state of `sim` at its current time.
  void sample(const CollisionMethod& sim);
  /// Time average of the translational kinetic energy, J.
  double kinetic_energy() const { return span() > 0 ? kinetic_integral_ / span() : last_kinetic_; }
  /// Time average of sqrt(T), sqrt(J) (collision rates scale with it).
  double root_temperature() const { return span() > 0 ? root_temperature_integral_ / span() : last_root_; }

 private:
  double span() const { return last_time_ - first_time_; }
  bool started_ = false;
  double first_time_ = 0, last_time_ = 0, last_kinetic_ = 0, last_root_ = 0;
  double kinetic_integral_ = 0, root_temperature_integral_ = 0;
};

/// One stretch of a run, as measured by the run loop.
struct RunStretch {
  std::string status = "completed";
  std::string message;
  double start_time = 0;               ///< s.
  RunStatistics start_statistics;      ///< Counters when the stretch began.
  double wall_seconds = 0;             ///< s.
  TimeAverages averages;
  const GasCoupling* gas = nullptr;    ///< The run's gas, if any.
  CouplingTimes gas_start;             ///< Its timers when the stretch began.
  std::string run_json;                ///< The "run" object: the run's identity; empty: none.
  std::string analysis_json;           ///< The "analysis" object (run_analysis.hpp); empty: none.
  const FlowBoundaries* flow = nullptr;  ///< The run's inflows and outflows, if any.
  FlowStart flow_start;                ///< Their counters when the stretch began.
};

/// The summary as JSON text.
std::string summary_json(const CollisionMethod& sim, const Scene& scene, const RunStretch& stretch);

/// Writes `text` to `path` atomically (temporary file, then rename).
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace carom
