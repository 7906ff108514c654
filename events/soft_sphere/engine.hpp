#pragma once
/// The soft-sphere DEM method (core/DESIGN.md, "Methods"): particles overlap slightly at contacts
/// and feel spring-dashpot forces (contact_model.hpp), integrated with velocity Verlet at a fixed
/// step, contacts found on Verlet lists (neighbour_list.hpp). A second implementation of
/// CollisionMethod, on the same scenes, outputs and gas coupling as the event-driven method.
///
/// Files: engine.cpp (construction, the step loop, actions, energies), contact_forces.cpp (the
/// force of every listed contact, the counters it books), engine_state_io.cpp (checkpoints),
/// flow_change.cpp (particles leaving and entering).
///
/// The step (velocity Verlet, as in LIGGGHTS and LAMMPS' nve/sphere):
///   v += dt/2 (F_c / m + a(v));  w += dt/2 T / I       (F_c, T: contact force and torque)
///   r += dt v                                           (periodic axes fold r into the box)
///   F_c, T from the contacts at the new positions with the half-step velocities
///   v += dt/2 (F_c / m + a(v));  w += dt/2 T / I
/// a(v) = drive - rate v is the particle's body acceleration: gravity, and with a gas the drag
/// and pressure-gradient forces of the fluid step, whose gas velocity, drag coefficient and
/// pressure gradient stay frozen for the fluid step while the drag follows the particle's own
/// velocity at every DEM step (the relax flight's forces, re-evaluated each step: a particle
/// that changes velocity in a contact feels the drag of its new velocity at once, which is what
/// the two-way coupling's momentum balance assumes).
#include <cstdint>
#include <string>
#include <vector>

#include "events/method.hpp"
#include "events/soft_sphere/contact_model.hpp"
#include "events/soft_sphere/neighbour_list.hpp"
#include "events/soft_sphere/options.hpp"

namespace carom {

/// A periodic or synchronising action of the soft-sphere method (see CollisionMethod).
struct SteppedAction {
  std::string name;
  double next_time = 0;  ///< s.
  double interval = 0;   ///< s.
  std::function<void()> action;             ///< Periodic: reads the run.
  std::function<void(GlobalStep&)> step;    ///< Synchronising: may change velocities, flights.
};

/// Contact durations of ended contacts, per species pair (symmetric, S x S).
struct ContactDurations {
  std::vector<std::uint64_t> count;
  std::vector<double> total;  ///< s.
};

class SoftSphereEngine final : public CollisionMethod {
 public:
  /// A fresh run. Throws std::invalid_argument naming the cause when the system cannot run:
  /// overlaps beyond max_overlap, a missing elastic constant, a step above the stability limit.
  SoftSphereEngine(System system, SoftSphereOptions options);
  /// A run restored from save_state's group.
  SoftSphereEngine(System system, SoftSphereOptions options, const h5::Group& saved);

  std::string_view kind() const override { return "soft_sphere"; }
  bool run_until(double t_end) override;
  void set_stop_flag(const volatile std::sig_atomic_t* flag) override { stop_flag_ = flag; }
  void add_periodic_action(std::string name, double first_time, double interval,
                           std::function<void()> action) override;
  void add_synchronising_action(std::string name, double first_time, double interval,
                                std::function<void(GlobalStep&)> step) override;
  double time() const override { return time_; }
  /// The next step boundary at or after t: stopping there changes nothing.
  double stop_time(double t) const override;
  const System& system() const override { return system_; }
  Vec3 position(std::size_t i) const override { return system_.particles.position[i]; }
  Vec3 velocity(std::size_t i) const override { return system_.particles.velocity[i]; }
  Vec3 spin(std::size_t i) const override { return system_.particles.spin[i]; }
  Energies energies() const override;
  const RunStatistics& statistics() const override { return statistics_; }
  /// Tags the bodies; before the first step, also books the contact forces of t = 0 on them
  /// (the first half step applies those).
  void tag_bodies(const std::vector<std::uint64_t>& ids) override;
  std::vector<MethodQuantity> quantities() const override;
  void save_state(const h5::Group& group) const override;

  /// The time step, s.
  double time_step() const { return time_step_; }
  /// The contact of species s and t.
  const PairContact& pair_contact(std::size_t s, std::size_t t) const {
    return pair_contacts_[s * system_.species.size() + t];
  }
  /// The contact of species s with wall w.
  const PairContact& wall_contact(std::size_t s, std::size_t w) const {
    return wall_contacts_[s * system_.walls.size() + w];
  }
  /// The shortest binary contact time of the scene at the impact speed of the default step, s.
  double shortest_contact_time() const { return shortest_contact_time_; }
  /// The impact speed the Hertz contact times were evaluated at, m/s.
  double impact_speed() const { return impact_speed_; }
  /// Contacts now (pairs, walls).
  std::size_t contacts_now() const;
  /// Ended contact durations per species pair.
  const ContactDurations& contact_durations() const { return durations_; }
  /// Steps taken since the start.
  std::uint64_t steps() const { return steps_; }

 private:
  void setup();              // contacts, step, masses; throws std::invalid_argument
  void sort_particles();     // spatial order in memory (fresh runs)
  void step(double dt);      // one velocity-Verlet step
  /// v += dt/2 (F/m + a(v)), w += dt/2 T/I, books the gas work; kDrift: then r += dt v and
  /// F = T = 0 (the step's first half), returning the largest squared speed, (m/s)^2.
  template <bool kDrift>
  double half_kick(double dt);
  /// Contact forces and torques at the current positions and velocities; the tangential springs
  /// advance by dt (0: evaluate only). clear: first set every force and torque to zero (else
  /// the caller has: half_kick<true>). Books counters and dissipation; throws MethodFailure.
  void compute_forces(double dt, bool clear);
  /// Books the work of the lossy contact forces of this step with the end-of-step velocities.
  void book_dissipation(double dt);
  void fire_due_actions(double t);
  /// Removes and adds particles (a flow step, all at time_): per-particle arrays follow, the
  /// contact histories of the remaining pairs are kept, forces are evaluated again
  /// (flow_change.cpp).
  void apply_change(const ParticleChange& change);
  void check_energy();       // the energy-growth detector; throws MethodFailure
  void hold_fixed_particles();
  [[noreturn]] void fail_overlap(std::int32_t i, std::int32_t j, double overlap, double radius) const;

  System system_;
  SoftSphereOptions options_;
  std::vector<PairContact> pair_contacts_;  // S x S
  std::vector<PairContact> wall_contacts_;  // S x W
  NeighbourList list_;
  std::vector<double> inverse_mass_, inverse_inertia_;  // 0 for fixed particles
  std::vector<Vec3> force_, torque_;                    // contact force and torque, N, N m
  /// A touching contact's forces whose work is booked at the end of the step.
  struct LossyContact {
    std::int32_t first, second;  // particles; second < 0: a wall
    Vec3 normal;                 // from the second body to the first
    Vec3 force;                  // normal dashpot + tangential force on the first, N
    Vec3 rolling_torque;         // on the first, N m
  };
  std::vector<LossyContact> lossy_;
  std::vector<RelaxFlight> flights_;
  std::vector<SteppedAction> actions_;
  std::vector<std::pair<std::string, double>> restored_action_times_;
  RunStatistics statistics_;
  TaggedImpulses& tagged_impulses() override { return statistics_.tagged; }
  ContactDurations durations_;
  double time_ = 0, time_step_ = 0;
  double shortest_contact_time_ = 0, impact_speed_ = 0;
  std::uint64_t steps_ = 0;
  double elastic_ = 0;      // stored in the springs at the last force evaluation, J
  double gas_work_ = 0;     // J
  double flow_energy_ = 0;  // brought in by entering particles minus taken out by leaving ones, J
  bool gas_forces_ = false; // a synchronising action has set flights (else gravity alone)
  double travelled_ = 0;    // bound on any particle's displacement since the list was built, m
  double energy_start_ = 0;   // energies().total() at the start, J
  double energy_scale_ = 0;   // largest kinetic + elastic energy seen, J
  double worst_overlap_ = 0;  // largest overlap / smaller radius seen
  const volatile std::sig_atomic_t* stop_flag_ = nullptr;
};

}  // namespace carom
