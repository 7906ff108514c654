#pragma once
/// Inflow and outflow (core/DESIGN.md, "Methods": the flow step), the same for every
/// collision method: at each flow step (a synchronising action, so every particle's state is as
/// of the step's time) the particles beyond an outlet plane leave, and the particles each inflow
/// owes by its mass flow rate since the start enter, placed at random without overlap in a slab
/// behind the inlet rectangle. The method applies the change (events/method.hpp,
/// ParticleChange). The inflows and outflows themselves: flow_definitions.hpp.
#include <cstdint>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "core/rng.hpp"
#include "core/system.hpp"
#include "events/flow/flow_definitions.hpp"
#include "events/method.hpp"

namespace carom {

/// What one inflow has done since the start.
struct InflowCounters {
  std::uint64_t entered = 0;  ///< Particles placed.
  double entered_mass = 0;    ///< Their mass, kg.
  /// Particles owed at the last step: mass_flow (t - start) / m - entered, >= 0; its integer
  /// part waits for a free place (blocked), its fraction for the next step.
  double owed = 0;
  std::uint64_t blocked_steps = 0;  ///< Flow steps at which an owed particle found no place.
  std::uint64_t failed_tries = 0;   ///< Random places tried and found taken.
  /// Particles owed whole but not placed at the last step (floor(owed)): 0 unless blocked.
  std::uint64_t waiting() const { return static_cast<std::uint64_t>(owed); }
};

/// What one outflow has taken since the start.
struct OutflowCounters {
  std::uint64_t left = 0;  ///< Particles removed.
  double left_mass = 0;    ///< Their mass, kg.
};

/// Runs the inflows and outflows of a run: the flow step, the counters, the checkpoint.
class FlowBoundaries {
 public:
  /// `system`: domain, walls, species, gravity (copied) and the particles present at
  /// start_time (for ids and counts). `seed`: the scene's seed; the inflows draw from a stream of
  /// their own derived from it. `interval`: the time between flow steps, s (for the default depth).
  /// Throws std::invalid_argument naming the inflow or outflow, the key and the allowed range
  /// (check_inflow, check_outflow, check_inflow_against_outflow).
  FlowBoundaries(std::vector<Inflow> inflows, std::vector<Outflow> outflows, const System& system,
                 std::uint64_t seed, double start_time, double interval);

  /// The flow step at `time` (>= the last step's): every particle's state is as of `time`.
  /// Books particle-seconds with the counts before the change, then appends to `change` the
  /// particles beyond an outlet (indices into `particles`, kept ascending and unique) and the
  /// particles the inflows owe (new ids, clock = time), placed clear of the particles that stay,
  /// of each other, of the walls and of the box. Throws std::invalid_argument when time goes back.
  void step(double time, const ParticleStore& particles, ParticleChange& change);

  /// The inflows (depth resolved: inflow_depth) and outflows, in scene order.
  const std::vector<Inflow>& inflows() const { return inflows_; }
  const std::vector<Outflow>& outflows() const { return outflows_; }
  /// Counters of inflow k / outflow k since the start.
  const InflowCounters& inflow_counters(std::size_t k) const { return inflow_counters_[k]; }
  const OutflowCounters& outflow_counters(std::size_t k) const { return outflow_counters_[k]; }

  /// A warning for a report when inflow k found its slab full at some step: how often, how
  /// many particles still wait, and what to change; "" when it never did.
  std::string blocked_message(std::size_t k) const;

  /// Integral over time of the number of particles of each species present, from the start to
  /// the last step, particle s: collision frequencies per particle present are count / this.
  const std::vector<double>& particle_seconds() const { return particle_seconds_; }
  /// The same integral up to `time` (>= the last step), the counts after the last step held.
  std::vector<double> particle_seconds_at(double time) const;
  /// Particles of each species present after the last step (at the start: the system's).
  const std::vector<std::uint64_t>& present() const { return present_; }
  /// All particles present after the last step.
  std::uint64_t present_total() const;
  /// Kinetic (translational + rotational) and potential (-m g . r) energy brought in by
  /// entering particles and taken out by leaving ones since the start, J (Energies::flow is
  /// in - out).
  double energy_in() const { return energy_in_; }
  double energy_out() const { return energy_out_; }

  /// Time of the last flow step (the start before the first), s.
  double last_time() const { return last_time_; }
  /// The id the next entering particle gets: 1 + the largest id ever seen.
  std::uint64_t next_id() const { return next_id_; }

  /// Writes the random generator, counters, clocks, next id and particle-seconds into `group`
  /// (a checkpoint), so that restore() continues bit for bit.
  void save(const h5::Group& group) const;
  /// Reads what save() wrote. Throws std::runtime_error (naming the file and object) when the
  /// group does not hold the state of the same inflows, outflows and species.
  void restore(const h5::Group& group);

 private:
  /// Places what inflow k owes at `time` into change.added; `obstacles_max_radius`: the
  /// largest radius among the particles that stay, m.
  void run_inflow(std::size_t k, double time, const ParticleStore& particles,
                  const std::vector<char>& leaving, double obstacles_max_radius,
                  ParticleChange& change);
  /// Kinetic plus potential energy of a particle, J.
  double energy(double mass, double inertia, const Vec3& r, const Vec3& v, const Vec3& w) const;

  std::vector<Inflow> inflows_;
  std::vector<Outflow> outflows_;
  Domain domain_;                 ///< The box.
  std::vector<Wall> walls_;       ///< Every wall (box walls included).
  std::vector<Species> species_;  ///< Particle kinds.
  Vec3 gravity_;                  ///< g, m/s^2 (for the potential energy).
  Rng rng_;
  double start_time_;  ///< s; the inflows owe mass_flow (t - start_time) in all.
  double last_time_;   ///< s.
  std::uint64_t next_id_ = 0;
  std::vector<InflowCounters> inflow_counters_;
  std::vector<OutflowCounters> outflow_counters_;
  std::vector<double> particle_seconds_;   ///< Per species, s.
  std::vector<std::uint64_t> present_;     ///< Per species after the last step.
  double energy_in_ = 0, energy_out_ = 0;  ///< J.
};

}  // namespace carom
