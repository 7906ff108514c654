#pragma once
/// Remedies for inelastic collapse and the detector that stops a run stuck in one.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace carom {

/// How a run deals with inelastic collapse (infinitely many collisions in finite time).
struct CollapseOptions {
  /// TC model (Luding & McNamara): a collision is elastic and smooth when either particle
  /// collided less than contact_time ago, s. 0 turns it off.
  double contact_time = 0.0;
  /// Collisions with normal approach speed below this are elastic (e -> 1), m/s. 0: off.
  double elastic_below_speed = 0.0;
  /// A particle with more than this many collisions within `stall_window` means collapse.
  std::uint64_t stall_collisions = 1000;
  /// Simulated window for the stall count, s. <= 0: 1e-9 of the system's collision time
  /// scale (smallest diameter over a reference speed), chosen when the run starts.
  double stall_window = 0.0;
  /// Lasting contacts: more collisions per particle within one TC contact_time than this,
  /// averaged over all particles over a window of at least 10 collisions per particle and 100
  /// contact times (5000 collisions per particle at the limit), stop the run (status
  /// "lasting_contacts"). Used with the TC model only (its contact_time is the time scale);
  /// 0 turns it off.
  double max_collisions_per_contact_time = 50.0;
  /// The same limit as a collision frequency per particle, 1/s, for any scene (with or without
  /// the TC model). < 0: max_collisions_per_contact_time / contact_time with the TC model, off
  /// without it; 0: off.
  double max_collision_frequency = -1.0;
  /// The collision-frequency limit this run uses, 1/s (0: none), as documented above.
  double collision_frequency_limit() const {
    if (max_collision_frequency >= 0.0) return max_collision_frequency;
    return contact_time > 0.0 ? max_collisions_per_contact_time / contact_time : 0.0;
  }
};

/// Thrown when the stall detector fires. The simulator is left in a consistent state.
class InelasticCollapse : public std::runtime_error {
 public:
  InelasticCollapse(const std::string& message, std::vector<std::uint64_t> particle_ids)
      : std::runtime_error(message), particle_ids(std::move(particle_ids)) {}
  std::vector<std::uint64_t> particle_ids;  ///< Ids of the particles caught in the collapse.
};

}  // namespace carom
