#pragma once
/// Counters booked exactly at events: collisions and impacts per species pair and wall, virial,
/// energy lost.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "events/tagged_impulses.hpp"

namespace carom {

struct RunStatistics {
  std::size_t species_count = 0;
  std::size_t wall_count = 0;
  /// Collisions between species s and t, stored symmetric at [s * S + t] and [t * S + s].
  std::vector<std::uint64_t> pair_collisions;
  /// Sum of the impulse magnitudes |J| of the collisions between species s and t, N s, stored
  /// symmetric like pair_collisions (divide by time and by the count of s: the momentum per
  /// second one particle of s receives from collisions with t, in magnitude).
  std::vector<double> pair_impulse;
  /// Collisions of species s with wall w at [s * W + w].
  std::vector<std::uint64_t> wall_collisions;
  /// Impacts: the collisions whose normal approach speed exceeds the scene's impact speed
  /// (System::impact_speed), stored like pair_collisions and wall_collisions. Every method
  /// counts them the same way; the slower collisions are the chatter of lasting contacts, whose
  /// number a hard-sphere method resolves one by one and a soft-sphere method as one contact.
  std::vector<std::uint64_t> pair_impacts;
  std::vector<std::uint64_t> wall_impacts;
  /// Total impulse given to each wall by the particles, N s (for wall pressures).
  std::vector<Eigen::Vector3d> wall_impulse;
  /// Collision virial sum over pair collisions of r_ij (x) J_i, in J s (divide by V t for stress).
  Eigen::Matrix3d virial = Eigen::Matrix3d::Zero();
  double dissipated_energy = 0;        ///< Kinetic energy lost in collisions, J.
  std::uint64_t events = 0;            ///< Events processed (valid ones).
  std::uint64_t invalid_events = 0;    ///< Events popped and dropped (lazy invalidation).
  std::uint64_t pair_events = 0;       ///< Pair collisions.
  std::uint64_t wall_events = 0;       ///< Wall collisions.
  std::uint64_t cell_crossings = 0;    ///< Neighbour-grid cell crossings.
  /// Collision impulses on the tagged bodies, by partner (kept by resize).
  TaggedImpulses tagged;

  void resize(std::size_t species, std::size_t walls) {
    species_count = species;
    wall_count = walls;
    pair_collisions.assign(species * species, 0);
    pair_impulse.assign(species * species, 0.0);
    wall_collisions.assign(species * walls, 0);
    pair_impacts.assign(species * species, 0);
    wall_impacts.assign(species * walls, 0);
    wall_impulse.assign(walls, Eigen::Vector3d::Zero());
  }
  /// Books one collision between species s and t (and an impact when `impact`).
  void count_pair(std::size_t s, std::size_t t, bool impact) {
    ++pair_collisions[s * species_count + t];
    if (s != t) ++pair_collisions[t * species_count + s];
    ++pair_events;
    if (!impact) return;
    ++pair_impacts[s * species_count + t];
    if (s != t) ++pair_impacts[t * species_count + s];
  }
  /// Books one collision of species s with wall w (and an impact when `impact`).
  void count_wall(std::size_t s, std::size_t w, bool impact) {
    ++wall_collisions[s * wall_count + w];
    ++wall_events;
    if (impact) ++wall_impacts[s * wall_count + w];
  }
  std::uint64_t pair(std::size_t s, std::size_t t) const { return pair_collisions[s * species_count + t]; }
  std::uint64_t pair_impact(std::size_t s, std::size_t t) const { return pair_impacts[s * species_count + t]; }
  std::uint64_t wall_impact(std::size_t s, std::size_t w) const { return wall_impacts[s * wall_count + w]; }
  double impulse(std::size_t s, std::size_t t) const { return pair_impulse[s * species_count + t]; }
  std::uint64_t wall(std::size_t s, std::size_t w) const { return wall_collisions[s * wall_count + w]; }
  /// All collisions (pair + wall).
  std::uint64_t collisions() const { return pair_events + wall_events; }
};

}  // namespace carom
