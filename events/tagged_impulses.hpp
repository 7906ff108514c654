#pragma once
/// Tagged bodies: chosen particles whose collision impulses are booked where each method resolves
/// a collision (core/DESIGN.md, "Analysis": the force on a tagged body in a particle cloud), by
/// partner: each species, each wall. The impulse booked is exactly what changed the body's
/// velocity, so m (v(t) - v(0)) equals the booked total to round-off when collisions are the only
/// forces (no gravity, no gas).
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"

namespace carom {

struct TaggedImpulses {
  /// Particle ids of the tagged bodies, in slot order (the order the scene gave).
  std::vector<std::uint64_t> ids;
  /// By method particle index: the body's slot, or -1 when it is not tagged. Empty: no body is
  /// tagged, the only test a collision pays then.
  std::vector<std::int32_t> slot_of;
  std::size_t species_count = 0;  ///< S: partner categories 0..S-1 are species.
  std::size_t wall_count = 0;     ///< W: partner categories S..S+W-1 are walls.
  /// Cumulative collision impulse on body k from partner category c at [k * (S + W) + c], N s.
  std::vector<Vec3> impulse;
  /// Soft spheres: the contact force on body k from category c in the present step, N (velocity
  /// Verlet applies it over two half steps, each booked as force * dt / 2). Zero otherwise.
  std::vector<Vec3> step_force;

  /// Partner categories: species then walls.
  std::size_t partners() const { return species_count + wall_count; }
  std::size_t body_count() const { return ids.size(); }
  /// Whether any body is tagged.
  bool any() const { return !slot_of.empty(); }

  /// Tags the particles with `tagged` ids; `method_ids` are the method's particle ids by index.
  /// Tagging again with the same ids (a resumed run) keeps the impulses booked so far and
  /// rebuilds slot_of; other ids, an unknown id or a duplicate throw std::invalid_argument.
  void tag(const std::vector<std::uint64_t>& tagged, const std::vector<std::uint64_t>& method_ids,
           std::size_t species, std::size_t walls);

  /// Books impulse J on particle i (species of its partner: partner_species) and -J on its
  /// partner j (species of i: species_i); either may be untagged. j < 0: no second body (a
  /// fictitious Monte Carlo partner).
  void book_pair(std::int32_t i, std::int32_t j, std::uint32_t species_i,
                 std::uint32_t partner_species, const Vec3& impulse_on_i) {
    const std::size_t C = partners();
    const std::int32_t ki = slot_of[i];
    if (ki >= 0) impulse[ki * C + partner_species] += impulse_on_i;
    if (j < 0) return;
    const std::int32_t kj = slot_of[j];
    if (kj >= 0) impulse[kj * C + species_i] -= impulse_on_i;
  }
  /// Books impulse J on particle i from wall w.
  void book_wall(std::int32_t i, std::size_t w, const Vec3& impulse_on_i) {
    const std::int32_t k = slot_of[i];
    if (k >= 0) impulse[k * partners() + species_count + w] += impulse_on_i;
  }
  /// Soft spheres: books the present step's forces over half a step, h = dt / 2.
  void book_half_step(double h) {
    for (std::size_t k = 0; k < impulse.size(); ++k) impulse[k] += h * step_force[k];
  }
  /// Body k's total collision impulse since the start, N s.
  Vec3 total(std::size_t k) const {
    Vec3 sum = Vec3::Zero();
    for (std::size_t c = 0; c < partners(); ++c) sum += impulse[k * partners() + c];
    return sum;
  }
};

}  // namespace carom
