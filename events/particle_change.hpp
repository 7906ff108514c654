#pragma once
/// What every method does alike when particles leave and enter at a synchronising action
/// (ParticleChange, method.hpp): check the change, price the energy it carries, follow the
/// particles in the per-particle arrays of the method. Each method's own part (its grid,
/// calendar, contact lists) is in its engine.
#include <cstddef>
#include <vector>

#include "core/system.hpp"
#include "events/method.hpp"
#include "events/tagged_impulses.hpp"

namespace carom {

/// Throws std::logic_error when `change` is not a change of `system`'s particles: removed
/// indices not ascending or out of range, an added particle of an unknown or fixed species, or
/// with a non-finite state, or whose clock is not `time`.
void check_particle_change(const ParticleChange& change, const System& system, double time);

/// Kinetic (translational and rotational) plus potential energy -m g . r of particle i, J.
inline double carried_energy(const ParticleStore& p, std::size_t i, const Vec3& gravity) {
  return 0.5 * (p.mass[i] * p.velocity[i].squaredNorm() + p.inertia[i] * p.spin[i].squaredNorm()) -
         p.mass[i] * gravity.dot(p.position[i]);
}

/// Energy the entering particles bring minus what the leaving ones (of `p`, states as of the
/// step) take out, J.
double change_energy(const ParticleChange& change, const ParticleStore& p, const Vec3& gravity);

/// Applies the change to the particle store and to each per-particle array of the method that
/// follows the store (`fill` is what a new particle's entry gets).
template <class T, class Allocator>
void follow_change(std::vector<T, Allocator>& column, const ParticleChange& change, const T& fill) {
  ParticleStore::erase_indices(column, change.removed);
  column.insert(column.end(), change.added.size(), fill);
}

/// Removes and adds the particles in the store, and points the tagged bodies' slots at their
/// new indices (a tagged body that left keeps its books, with no particle).
void apply_particle_change(const ParticleChange& change, ParticleStore& particles,
                           TaggedImpulses& tagged);

}  // namespace carom
