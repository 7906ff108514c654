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
///
/// Relax flights have no closed-form contact time; their predictions first end the candidates
/// that cannot be reached at all (reach_tests, may_reach: a bound on how far each can fly), in
/// the same way. Both walk the grid's cells with gather_candidates.
#include <cassert>
#include <cstdint>

#include "core/cell_grid.hpp"
#include "core/domain.hpp"
#include "core/relax_flight.hpp"
#include "core/roots.hpp"
#include "core/vec3.hpp"

namespace carom {

/// A separation's components (dx, dy, dz) mapped to the nearest periodic image in place, as
/// Domain::minimum_image maps a vector: the scalar tests keep their components apart, as the
/// batch keeps them in columns.
inline void nearest_image(const Domain& domain, double& dx, double& dy, double& dz) {
  Vec3 dr(dx, dy, dz);
  domain.minimum_image(dr);
  dx = dr.x();
  dy = dr.y();
  dz = dr.z();
}

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
  if constexpr (kImage) nearest_image(domain, dx, dy, dz);
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

/// Hands the particles of the given cells but `self` (flat indices into `head`; lists linked by
/// `next`, where next[-1] = -1), in the cells' order, to `batch` as records of `records`, and
/// calls test(found) whenever it is full and once for the rest (if any); test reads
/// batch.state[0, found). The walk is the inner loop of every prediction: the cells' first
/// particles are loaded before any list is walked (independent loads, and no branch per cell:
/// about half are empty), and a list's first kUnrolled places are taken without a branch on its
/// length (a place past the end reads next[-1] and is written but not counted), so that a loop's
/// exit, mispredicted about once per cell, is reached only by longer lists. Two places suit a
/// dense fluid (0, 1 or 2 particles a cell: deeper costs 6 % at phi = 0.40), four the lists of
/// 3-5 that fines among large spheres make (tests/bench/README.md, "The candidate walk"). A
/// particle is written in any case and counted only when it is a candidate (not self, not past
/// the end), so the next write replaces it. Any depth hands over the same candidates in the same
/// order. kPrefetch (large systems, where the records and lists miss every cache) starts loading
/// each list's second place, each first particle's record and its event counter (`counters`,
/// which the prediction reads for its partner) as soon as the cell's first particle is known:
/// those loads then wait on one load, not on the walk (at N = 1e6, 1.24 times the collisions per
/// second, and 1.11 more with the counters, tests/bench/README.md). These hints load into the L2
/// (kWalkHint, `prefetcht1`), not the L1: the walk asks for some 45 lines at once, and into the
/// L2 they gave N = 1e6 1.06-1.10 times the collisions per second of L1 hints in short windows
/// (tests/bench/README.md, "The walk's own hints into the L2").
/// `counters` is required with kPrefetch and unread without it. Hints only: nothing read changes.
template <int kUnrolled, bool kPrefetch = false, class Test>
[[gnu::always_inline]] inline void gather_candidates(std::int32_t self, const std::int32_t* head,
                                                     const std::int32_t* next,
                                                     const std::int32_t* cells, int count,
                                                     const PairState* records, PairBatch& batch,
                                                     Test&& test,
                                                     const std::uint32_t* counters = nullptr) {
  assert(!kPrefetch || counters != nullptr);
  // __builtin_prefetch's locality: 2 is `prefetcht1` on x86-64 (into the L2), 3 `prefetcht0`.
  constexpr int kWalkHint = 2;
  std::int32_t first[HierarchicalGrid::kMaxBlock];
  int occupied = 0;
  for (int c = 0; c < count; ++c) {
    const std::int32_t j = head[cells[c]];
    if constexpr (kPrefetch) {
      __builtin_prefetch(next + j, 0, kWalkHint);  // next[-1] is there (an empty cell)
      const std::int32_t k = j < 0 ? 0 : j;
      __builtin_prefetch(records + k, 0, kWalkHint);
      __builtin_prefetch(counters + k, 0, kWalkHint);
    }
    first[occupied] = j;
    occupied += j >= 0;
  }
  int found = 0;
  for (int c = 0; c < occupied; ++c) {
    if (found > PairBatch::kCapacity - kUnrolled) {
      test(found);
      found = 0;
    }
    const std::int32_t j1 = first[c];  // never past the end
    batch.state[found] = records + j1;
    found += j1 != self;
    std::int32_t j = next[j1];
    if constexpr (kUnrolled == 2) {
      // The second place, and the loop entered only from a present second (this form measured
      // fewer instructions for the dense fluid than the general one below).
      const bool second = j >= 0;
      batch.state[found] = records + (second ? j : j1);
      if constexpr (kPrefetch) __builtin_prefetch(records + (second ? j : j1), 0, kWalkHint);
      found += second & (j != self);
      j = second ? next[j] : -1;
    } else {
      // Places 2..kUnrolled: each written (self for a place past the end) and counted when it
      // holds a candidate; next[-1] = -1 keeps the walk going past the end.
      for (int k = 1; k < kUnrolled; ++k) {
        const bool present = j >= 0;
        batch.state[found] = records + (present ? j : self);
        found += present & (j != self);
        j = next[j];
      }
    }
    for (; j >= 0; j = next[j]) {
      if (found == PairBatch::kCapacity) {
        test(found);
        found = 0;
      }
      batch.state[found] = records + j;
      found += j != self;
    }
  }
  if (found > 0) test(found);
}

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

/// A relax prediction's query for the reach test: whether a candidate can come within contact
/// before `end` at all, bounded without square roots (see relax_collision).
struct ReachQuery {
  Vec3 position;  ///< The query's stored position, m.
  double radius;  ///< m.
  double sweep;   ///< Bound on how far the query flies before `end` (its reach_bound), m.
  double end;     ///< s.
  RelaxFlightBounds bounds;  ///< Bounds on every candidate's flight.
  Domain domain;             ///< For the periodic images (used with kImage only).
  // For the line test (lines_apart) only:
  Vec3 velocity = Vec3::Zero();  ///< The query's stored velocity, m/s.
  double clock = 0.0;            ///< The query's clock, s.
  double acceleration = 0.0;     ///< |a(v)| of the query's stored state (its flight), m/s^2.
};

/// Whether candidate b may come within contact of the query before q.end: false when the
/// distance of the stored positions exceeds the radii plus both reach bounds (b's from its
/// velocity and the flights' bounds: RelaxFlightBounds::reach_bound), with a relative margin of
/// 1e-12 over the round-off by which a computed sum of magnitudes may fall short of a computed
/// length. The scalar reference for reach_tests.
template <bool kImage>
inline bool may_reach(const ReachQuery& q, const PairState& b) {
  double dx = q.position.x() - b.position.x();
  double dy = q.position.y() - b.position.y();
  double dz = q.position.z() - b.position.z();
  if constexpr (kImage) nearest_image(q.domain, dx, dy, dz);
  const double sweep = q.bounds.reach_bound(b.velocity, q.end - b.clock);
  const double reach = (q.radius + b.radius + q.sweep + sweep) * (1.0 + 1e-12);
  return !(dx * dx + dy * dy + dz * dz > reach * reach);
}

/// Whether candidate b and the query cannot touch before q.end, from their stored states alone
/// (no exponential, no square root, no flight read). Each particle strays from the straight
/// line p + v (t - clock) of its stored state by at most |a(v)| (t - clock)^2 / 2 (its
/// acceleration only decays: relax_flight.hpp); the query's |a(v)| is q.acceleration, b's is
/// bounded by q.bounds (|drive| + rate |v|, lengths as sums of magnitudes). So if the relative
/// line, from the later clock t_ref to q.end, keeps farther than the radii plus both strays,
/// they cannot touch. Its closest approach is taken without a division: at t_ref when the
/// pair separates there, at q.end when it still approaches there, else |d x u| / |u| (no
/// cancellation where d and u are nearly parallel). A relative margin of 1e-9 covers the
/// round-off of the lengths and of the trajectories themselves, far above the touching
/// tolerance of the contact search: every pair it ends, relax_pair_time's exact tests and
/// search end too (tests/test_pair_batch.cpp checks that on random pairs). The scalar reference
/// for reach_tests<kImage, true>; the relax predictions' most frequent rejection (about three
/// candidates in four that pass may_reach in a dense bed: pairs in contact that separate).
template <bool kImage>
inline bool lines_apart(const ReachQuery& q, const PairState& b) {
  const double t_ref = q.clock > b.clock ? q.clock : b.clock;
  const double dt_a = t_ref - q.clock, dt_b = t_ref - b.clock, horizon = q.end - t_ref;
  double dx = q.position.x() - b.position.x() + dt_a * q.velocity.x() - dt_b * b.velocity.x();
  double dy = q.position.y() - b.position.y() + dt_a * q.velocity.y() - dt_b * b.velocity.y();
  double dz = q.position.z() - b.position.z() + dt_a * q.velocity.z() - dt_b * b.velocity.z();
  if constexpr (kImage) nearest_image(q.domain, dx, dy, dz);
  const double ux = q.velocity.x() - b.velocity.x();
  const double uy = q.velocity.y() - b.velocity.y();
  const double uz = q.velocity.z() - b.velocity.z();
  const double speed_b =
      std::abs(b.velocity.x()) + std::abs(b.velocity.y()) + std::abs(b.velocity.z());
  const double acceleration_b = q.bounds.drive + q.bounds.rate * speed_b;
  const double span_a = q.end - q.clock, span_b = q.end - b.clock;
  const double stray = 0.5 * (q.acceleration * span_a * span_a + acceleration_b * span_b * span_b);
  const double reach = (q.radius + b.radius + stray) * (1.0 + 1e-9);
  const double reach2 = reach * reach;
  const double u2 = ux * ux + uy * uy + uz * uz, du = dx * ux + dy * uy + dz * uz;
  const double ex = dx + horizon * ux, ey = dy + horizon * uy, ez = dz + horizon * uz;
  const double cx = dy * uz - dz * uy, cy = dz * ux - dx * uz, cz = dx * uy - dy * ux;
  const bool at_start = dx * dx + dy * dy + dz * dz > reach2;
  const bool at_end = ex * ex + ey * ey + ez * ez > reach2;
  const bool between = cx * cx + cy * cy + cz * cz > reach2 * u2;
  return du >= 0.0 ? at_start : (-du >= horizon * u2 ? at_end : between);
}

/// The candidates k < batch.count for which may_reach<kImage>(query, candidate k) holds (and,
/// with kLines, lines_apart<kImage> does not), as the bits k of the result (the same decisions
/// bit for bit), four candidates at a time. batch.time and batch.earliest are left as they are.
template <bool kImage, bool kLines = false>
std::uint64_t reach_tests(const ReachQuery& query, const PairBatch& batch);
static_assert(PairBatch::kCapacity <= 64, "reach_tests answers with one bit per candidate");

/// Fills batch.time[k] for k < batch.count with
/// pair_contact<kGravity, kImage>(query..., candidate k...), bit for bit, and batch.earliest
/// with the smallest k whose time is the least of them (-1 when all are kNever).
template <bool kGravity, bool kImage>
void contact_times(const PairQuery& query, PairBatch& batch);

}  // namespace carom
