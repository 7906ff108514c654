#pragma once
/// A collision method (core/DESIGN.md, "Methods"): one way of moving particles and resolving their
/// collisions, behind the small interface that the run loop, outputs, checkpoints, analysis,
/// sweeps and the gas coupling are written against. The event-driven hard-sphere engine
/// (events/event_driven/) is the first implementation; time-stepped methods (soft spheres,
/// Monte Carlo collisions) implement the same calls, as each comment says.
#include <csignal>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/hdf5.hpp"
#include "core/relax_flight.hpp"
#include "core/system.hpp"
#include "events/statistics.hpp"

namespace carom {

class SideThread;  // core/side_thread.hpp

/// Kinetic, potential, elastic and dissipated energy at the current time, J.
struct Energies {
  double translational = 0;  ///< sum m v^2 / 2.
  double rotational = 0;     ///< sum I w^2 / 2.
  double potential = 0;      ///< sum -m g . r (positions folded into the box).
  double elastic = 0;        ///< Stored in the springs of the contacts now (soft spheres; else 0).
  double dissipated = 0;     ///< Lost in collisions since the start (damping and friction).
  /// Work done on the particles by the gas forces (drag, pressure gradient) since the start;
  /// 0 where a method does not book it.
  double gas_work = 0;
  /// Energy (kinetic + potential) that entering particles brought in minus what leaving ones
  /// took out, since the start (inflow, outflow), J.
  double flow = 0;
  /// translational + rotational + potential + elastic + dissipated - gas_work - flow: constant
  /// in an exact run.
  double total() const {
    return translational + rotational + potential + elastic + dissipated - gas_work - flow;
  }
};

/// A number a method measures beyond RunStatistics (a soft-sphere run's coordination number,
/// mean contact duration, time step), for summary.json and report.md.
struct MethodQuantity {
  std::string name;  ///< snake_case key, e.g. "coordination_number".
  double value = 0;  ///< In `unit`.
  std::string unit;  ///< SI unit, "" for a pure number.
  std::string what;  ///< One line saying what it is.
};

/// A method that cannot go on (an unstable step, overlaps beyond bounds): the run stops with
/// `status` in summary.json and the message, which names the cause and the remedy. The state
/// it stopped in may be mid-step: the run writes its summary and report, and no checkpoint of
/// it (the last checkpoint written before stays).
class MethodFailure : public std::runtime_error {
 public:
  MethodFailure(std::string status, const std::string& message)
      : std::runtime_error(message), status(std::move(status)) {}
  std::string status;  ///< snake_case, e.g. "soft_sphere_unstable".
};

/// Particles that leave and enter at a synchronising action: the removal and insertion events of
/// outflows and inflows (core/DESIGN.md, "Methods"; events/flow/). The method removes and adds them
/// after the action: the remaining particles keep their order, the new ones are appended in the
/// order given, with a flight of gravity alone until the next fluid step.
struct ParticleChange {
  std::vector<std::size_t> removed;  ///< Indices (the method's order) of particles that leave, ascending.
  ParticleStore added;               ///< Particles that enter, their states as of the step's time.
  bool empty() const { return removed.empty() && added.size() == 0; }
};

/// What a synchronising action (the fluid step, a drag kick, the flow step) sees and may change:
/// every particle's state as of `time`.
struct GlobalStep {
  double time;                        ///< s.
  ParticleStore& particles;           ///< States as of `time`; velocities may be changed.
  /// Each particle's flight until the next step: the drag and pressure-gradient forces frozen
  /// for one fluid step (RelaxFlight: rate K/m, drive). Event-driven relax flights fly them
  /// exactly; a time-stepped method applies them as forces at each of its steps.
  std::vector<RelaxFlight>& flights;
  /// Particles to remove and add (the flow step); the action must not resize `particles` itself.
  ParticleChange change{};
  /// A second thread for the action's per-particle loops (for_chunks), or null.
  /// The action's results must not depend on it.
  SideThread* side = nullptr;
};

/// The interface a collision method offers the rest of carom. Particle indices are the
/// method's own order (stable for the method's life; ids are in system().particles.id).
class CollisionMethod {
 public:
  virtual ~CollisionMethod() = default;

  /// The scene name of the method (`[method] kind`), e.g. "event_driven".
  virtual std::string_view kind() const = 0;

  /// Advances the run to time t_end, s. Returns true when it got there, false when the stop flag
  /// was raised first (the run then stands at a consistent state that can be checkpointed and
  /// resumed). Event-driven: processes every event up to t_end. Time-stepped: takes whole steps
  /// and ends exactly at t_end (global events fall on step boundaries; t_end is one). Throws
  /// InelasticCollapse (or the method's own failure, e.g. an unstable step) with a diagnostic.
  virtual bool run_until(double t_end) = 0;
  /// A flag (set by a signal handler) that run_until checks every few thousand events or steps.
  virtual void set_stop_flag(const volatile std::sig_atomic_t* flag) = 0;

  /// Registers `action` to run at first_time and then every interval seconds: it reads the run
  /// (outputs, samples) and changes no particle. A saved run resumes it at its saved next time.
  virtual void add_periodic_action(std::string name, double first_time, double interval,
                                   std::function<void()> action) = 0;
  /// Registers a synchronising action, the hook of the fluid step and of drag kicks: at
  /// first_time + k interval every particle is brought to that time, `step` may change
  /// velocities and flights, and the method goes on from the new state. Event-driven: predictions
  /// never reach past the next one. Time-stepped: the step sizes are cut to land on it.
  virtual void add_synchronising_action(std::string name, double first_time, double interval,
                                        std::function<void(GlobalStep&)> step) = 0;

  /// The current time, s.
  virtual double time() const = 0;
  /// The earliest time >= t at which run_until can stop without changing the run: t itself for
  /// the event-driven method (its run_until end touches no particle); the next step boundary for
  /// a time-stepped method, whose last step would otherwise be cut short. The run loop ends its
  /// wall-clock chunks there, so that a run does not depend on how fast the machine is.
  virtual double stop_time(double t) const { return t; }
  /// Box, walls, species, laws, and the particles' constant properties (radius, mass, species,
  /// id). Their dynamic state is read through position(i), velocity(i), spin(i).
  virtual const System& system() const = 0;
  std::size_t particle_count() const { return system().particles.size(); }
  /// Particle i's position at the current time, m.
  virtual Vec3 position(std::size_t i) const = 0;
  /// Particle i's velocity at the current time, m/s.
  virtual Vec3 velocity(std::size_t i) const = 0;
  /// Particle i's spin at the current time, rad/s.
  virtual Vec3 spin(std::size_t i) const = 0;
  /// Energies at the current time (dissipated: since the start).
  virtual Energies energies() const = 0;
  /// Counters since the start: collisions per species pair and per wall (a time-stepped method
  /// counts a collision when a contact begins), impulses, virial, dissipated energy, events
  /// (time-stepped: steps).
  virtual const RunStatistics& statistics() const = 0;
  /// Tags the particles with these ids (tagged bodies): from now on the collision impulse on
  /// each, by partner species and wall, is booked where the method resolves collisions
  /// (statistics().tagged). A resumed method is tagged again with the same ids and keeps its
  /// books. Throws std::invalid_argument for an unknown or repeated id, or ids that differ from
  /// a saved state's.
  virtual void tag_bodies(const std::vector<std::uint64_t>& ids) {
    tagged_impulses().tag(ids, system().particles.id, system().species.size(),
                          system().walls.size());
  }
  /// What the method measures beyond statistics() (none for the event-driven method).
  virtual std::vector<MethodQuantity> quantities() const { return {}; }

  /// Writes everything needed to continue exactly (bit for bit) into `group` (a checkpoint):
  /// the dynamic state, counters and clocks; the scene supplies the rest again. The group's
  /// attributes "method" and "time" hold kind() and time().
  virtual void save_state(const h5::Group& group) const = 0;

 protected:
  /// The tagged bodies' books inside the method's counters (statistics().tagged).
  virtual TaggedImpulses& tagged_impulses() = 0;
};

}  // namespace carom
