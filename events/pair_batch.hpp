#pragma once
/// Contact times of one particle against a batch of candidate partners, several at a time.
///
/// The pair test is the innermost loop of the program (more than half of the run time of a
/// dense fluid). Tested one partner at a time it costs about 70 instructions and a branch that
/// goes either way at random (approaching or receding); here the candidates' states are first
/// copied into columns (structure of arrays), then the same arithmetic runs four partners at a
/// time without branches (SSE2 on any x86-64, AVX2 where the processor has it, picked at run
/// time). The operations and their order are those of pair_contact (below), so the times are
/// the same to the last bit (test_predictions checks it), and no fused multiply-add is used.
#include <cstdint>

#include "core/domain.hpp"
#include "core/roots.hpp"
#include "core/vec3.hpp"

namespace carom {

/// Contact time of partner b with particle a, both moving ballistically under the same gravity,
/// each state given at its own clock (s); kImage takes the nearest periodic image. The scalar
/// reference for PairBatch.
template <bool kGravity, bool kImage>
inline double pair_contact(const Vec3& position_a, const Vec3& velocity_a, double clock_a,
                           double radius_a, const Vec3& position_b, const Vec3& velocity_b,
                           double clock_b, double radius_b, const Vec3& gravity, const Domain& domain) {
  const double t_ref = clock_a > clock_b ? clock_a : clock_b;
  const double dt_a = t_ref - clock_a, dt_b = t_ref - clock_b;
  double dx = position_a.x() - position_b.x() + dt_a * velocity_a.x() - dt_b * velocity_b.x();
  double dy = position_a.y() - position_b.y() + dt_a * velocity_a.y() - dt_b * velocity_b.y();
  double dz = position_a.z() - position_b.z() + dt_a * velocity_a.z() - dt_b * velocity_b.z();
  double ux = velocity_a.x() - velocity_b.x();
  double uy = velocity_a.y() - velocity_b.y();
  double uz = velocity_a.z() - velocity_b.z();
  if constexpr (kGravity) {
    const double half = 0.5 * (dt_a * dt_a - dt_b * dt_b), lag = dt_a - dt_b;
    dx += half * gravity.x();
    dy += half * gravity.y();
    dz += half * gravity.z();
    ux += lag * gravity.x();
    uy += lag * gravity.y();
    uz += lag * gravity.z();
  }
  if constexpr (kImage) {
    Vec3 dr(dx, dy, dz);
    domain.minimum_image(dr);
    dx = dr.x();
    dy = dr.y();
    dz = dr.z();
  }
  return t_ref + sphere_contact_time(Vec3(dx, dy, dz), Vec3(ux, uy, uz), radius_a + radius_b);
}

/// A batch of candidate partners in columns, and their contact times with one particle.
struct PairBatch {
  /// Most candidates per batch (a multiple of the vector width, 4).
  static constexpr int kCapacity = 64;
  alignas(32) double px[kCapacity], py[kCapacity], pz[kCapacity];  ///< Positions, m.
  alignas(32) double vx[kCapacity], vy[kCapacity], vz[kCapacity];  ///< Velocities, m/s.
  alignas(32) double clock[kCapacity];   ///< Clocks of the states, s.
  alignas(32) double radius[kCapacity];  ///< m.
  alignas(32) double time[kCapacity];    ///< Output: contact time with the query, s, or kNever.
  std::int32_t partner[kCapacity];       ///< Particle index of each candidate.
  int count = 0;                         ///< Candidates filled in.

  /// Appends a candidate.
  void add(std::int32_t j, const Vec3& position, const Vec3& velocity, double clock_j, double radius_j) {
    px[count] = position.x();
    py[count] = position.y();
    pz[count] = position.z();
    vx[count] = velocity.x();
    vy[count] = velocity.y();
    vz[count] = velocity.z();
    clock[count] = clock_j;
    radius[count] = radius_j;
    partner[count] = j;
    ++count;
  }
};

/// The particle whose contacts are sought, with what the batch test needs of the system.
struct PairQuery {
  Vec3 position, velocity;  ///< m, m/s, at `clock`.
  double clock;             ///< s.
  double radius;            ///< m.
  Vec3 gravity;             ///< m/s^2 (used with kGravity only).
  Domain domain;            ///< For the periodic images (used with kImage only).
};

/// Fills batch.time[k] for k < batch.count with
/// pair_contact<kGravity, kImage>(query..., candidate k...), bit for bit.
template <bool kGravity, bool kImage>
void contact_times(const PairQuery& query, PairBatch& batch);

}  // namespace carom
