#pragma once
/// Contact times of one particle against a batch of candidate partners, several at a time.
///
/// The pair test is the innermost loop of the program (more than half of the run time of a
/// dense fluid). Tested one partner at a time it costs about 70 instructions and a branch that
/// goes either way at random (approaching or receding); here four candidates' records are
/// loaded and transposed into columns in registers, then the same arithmetic runs on the four
/// at once without branches (SSE2 on any x86-64, AVX2 where the processor has it, picked at
/// run time). The operations and their order are those of pair_contact (below), so the times are
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

/// The part of a particle's state that a pair test reads, packed into one cache line: two
/// halves of four doubles each, {position, clock} and {velocity, radius}. Predictions visit
/// partners in no particular order, so one line per partner beats four separate arrays, and
/// the batch test loads four records as four vectors per half and transposes them in
/// registers.
struct alignas(64) PairState {
  Vec3 position;  ///< m, at `clock`.
  double clock;   ///< s.
  Vec3 velocity;  ///< m/s, at `clock`.
  double radius;  ///< m.
};
static_assert(sizeof(PairState) == 64, "one cache line, two halves of four doubles");

/// A batch of candidate partners (their records, not copies) and their contact times with one
/// particle.
struct PairBatch {
  /// Most candidates per batch (a multiple of the vector width, 4).
  static constexpr int kCapacity = 64;
  /// Each candidate's record; three spare entries let pad_to_vectors write without a branch.
  const PairState* state[kCapacity + 3];
  alignas(32) double time[kCapacity];  ///< Output: contact time with the query, s, or kNever.
  int count = 0;                       ///< Candidates filled in.
  /// Output: the first candidate with the earliest contact time, or -1 if none ever touches.
  int earliest = -1;

  /// Appends a candidate.
  void add(const PairState* record) { state[count++] = record; }
  /// Pads `found` candidates to whole vectors of four with `padding` (a partner that never
  /// touches), without a branch (how many are missing is unpredictable).
  void pad_to_vectors(int found, const PairState* padding) {
    state[found] = state[found + 1] = state[found + 2] = padding;
    count = (found + 3) & ~3;
  }
};

/// The particle whose contacts are sought, with what the batch test needs of the system.
struct PairQuery {
  Vec3 position, velocity;  ///< m, m/s, at `clock`.
  double clock;             ///< s.
  double radius;            ///< m.
  /// A partner that never touches the query (its own state, radius 0: no relative motion),
  /// to pad a batch to whole vectors.
  PairState never_touching() const { return PairState{position, clock, velocity, 0.0}; }
  Vec3 gravity;             ///< m/s^2 (used with kGravity only).
  Domain domain;            ///< For the periodic images (used with kImage only).
};

/// Fills batch.time[k] for k < batch.count with
/// pair_contact<kGravity, kImage>(query..., candidate k...), bit for bit, and batch.earliest
/// with the smallest k whose time is the least of them (-1 when all are kNever).
template <bool kGravity, bool kImage>
void contact_times(const PairQuery& query, PairBatch& batch);

}  // namespace carom
