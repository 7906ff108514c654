#pragma once
/// The particle store: structure-of-arrays, hot dynamic state apart from cold bookkeeping.
#include <cstdint>
#include <vector>

#include "vec3.hpp"

namespace carom {

/// Every particle's state. Positions and velocities are stored as of the particle's own
/// clock ("delayed states"): a particle is advanced only when it takes part in an event.
struct ParticleStore {
  // Hot: read at every prediction. (What a method keeps about its own bookkeeping, such as
  // event counters or the time of the last collision, lives in the method, not here.)
  std::vector<Vec3> position;   ///< Centre r_i at time clock[i], m.
  std::vector<Vec3> velocity;   ///< Velocity v_i at time clock[i], m/s.
  std::vector<double> clock;    ///< t_i: the time the stored state refers to, s.
  std::vector<double> radius;   ///< a_i, m.

  // Warm: read at collisions.
  std::vector<Vec3> spin;       ///< Angular velocity w_i, rad/s (constant in free flight).
  std::vector<double> mass;     ///< m_i, kg.
  std::vector<double> inertia;  ///< I_i = (2/5) m_i a_i^2, kg m^2.

  // Cold.
  std::vector<std::uint32_t> species;  ///< Index into the species list.
  std::vector<std::uint64_t> id;       ///< Stable user-visible identifier.

  std::size_t size() const { return position.size(); }

  /// Appends one particle at rest in time at `time`.
  void add(const Vec3& r, const Vec3& v, const Vec3& w, double a, double m, double inertia_value,
           std::uint32_t species_index, std::uint64_t particle_id, double time = 0.0) {
    position.push_back(r);
    velocity.push_back(v);
    clock.push_back(time);
    radius.push_back(a);
    spin.push_back(w);
    mass.push_back(m);
    inertia.push_back(inertia_value);
    species.push_back(species_index);
    id.push_back(particle_id);
  }

  /// Calls f(column, others' same column...) for every per-particle array of this store: the
  /// one list of the columns, which erase, append, permute and pop_back go through.
  template <class F, class... Others>
  void for_each_column(F&& f, Others&&... others) {
    f(position, others.position...);
    f(velocity, others.velocity...);
    f(clock, others.clock...);
    f(radius, others.radius...);
    f(spin, others.spin...);
    f(mass, others.mass...);
    f(inertia, others.inertia...);
    f(species, others.species...);
    f(id, others.id...);
  }

  /// Removes the last particle.
  void pop_back() {
    for_each_column([](auto& column) { column.pop_back(); });
  }

  /// Removes the particles at `indices` (ascending, each once); the others keep their order.
  void erase(const std::vector<std::size_t>& indices) {
    for_each_column([&](auto& column) { erase_indices(column, indices); });
  }

  /// Appends every particle of `other`, in its order.
  void append(const ParticleStore& other) {
    for_each_column(
        [](auto& column, const auto& added) {
          column.insert(column.end(), added.begin(), added.end());
        },
        other);
  }

  /// Removes the entries at `indices` (ascending, each once) from `column`, keeping the order of
  /// the others: the per-particle arrays of a method follow its particles with this.
  template <class Column>
  static void erase_indices(Column& column, const std::vector<std::size_t>& indices) {
    std::size_t next = 0, kept = 0;
    for (std::size_t i = 0; i < column.size(); ++i) {
      if (next < indices.size() && indices[next] == i) {
        ++next;
        continue;
      }
      if (kept != i) column[kept] = std::move(column[i]);
      ++kept;
    }
    column.resize(kept);
  }

  /// Reorders every array so that new particle k is old particle order[k].
  void permute(const std::vector<std::size_t>& order) {
    for_each_column([&](auto& column) {
      auto old = column;
      for (std::size_t k = 0; k < order.size(); ++k) column[k] = old[order[k]];
    });
  }
};

}  // namespace carom
