// The batch pair test and the relax reach test (see pair_batch.hpp): pair_contact's and
// may_reach's arithmetic on four partners at once.
//
// Written with GCC/Clang vector extensions: a 4-wide vector of doubles compiles to two SSE2
// operations in the default clone and to one AVX operation in the "avx2" clone (chosen at
// load time). Neither target has fused multiply-add, so each operation rounds exactly as in
// the scalar code. This file is compiled with -fno-math-errno so that the square roots
// vectorise.
#include "pair_batch.hpp"

#include <cmath>

namespace carom {

namespace {
// Every helper taking or returning a vector is forced inline: called out of line from the avx2
// clone, a default-target helper would receive its 32-byte arguments under the other calling
// convention (ymm registers against memory), which is what the -O0 debug build did.
#define CAROM_LANES_INLINE inline __attribute__((always_inline))
using Lanes = double __attribute__((vector_size(32)));
using Mask = long long __attribute__((vector_size(32)));
// Lanes a0..a3 b0..b3 picked by four indices: GCC's __builtin_shuffle, clang's
// __builtin_shufflevector (the fuzzing build uses clang); the same lanes either way.
#if defined(__clang__)
#define CAROM_SHUFFLE(a, b, i, j, k, l) __builtin_shufflevector(a, b, i, j, k, l)
#else
#define CAROM_SHUFFLE(a, b, i, j, k, l) __builtin_shuffle(a, b, Mask{i, j, k, l})
#endif

CAROM_LANES_INLINE Lanes load(const double* p) {
  Lanes v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
CAROM_LANES_INLINE Lanes splat(double x) { return Lanes{x, x, x, x}; }
CAROM_LANES_INLINE Lanes select(Mask m, Lanes a, Lanes b) { return m ? a : b; }

/// Four records' halves (rows) as four columns: columns[c][k] = rows[k][c].
CAROM_LANES_INLINE void transpose(const Lanes (&rows)[4], Lanes (&columns)[4]) {
  const Lanes even01 = CAROM_SHUFFLE(rows[0], rows[1], 0, 4, 2, 6);
  const Lanes odd01 = CAROM_SHUFFLE(rows[0], rows[1], 1, 5, 3, 7);
  const Lanes even23 = CAROM_SHUFFLE(rows[2], rows[3], 0, 4, 2, 6);
  const Lanes odd23 = CAROM_SHUFFLE(rows[2], rows[3], 1, 5, 3, 7);
  columns[0] = CAROM_SHUFFLE(even01, even23, 0, 1, 4, 5);
  columns[1] = CAROM_SHUFFLE(odd01, odd23, 0, 1, 4, 5);
  columns[2] = CAROM_SHUFFLE(even01, even23, 2, 3, 6, 7);
  columns[3] = CAROM_SHUFFLE(odd01, odd23, 2, 3, 6, 7);
}

/// Candidates k..k+3's records as columns: place = {x, y, z, clock}, motion = {vx, vy, vz,
/// radius}, each with the four candidates in its lanes.
CAROM_LANES_INLINE void load_records(const PairBatch& batch, int k, Lanes (&place)[4],
                                     Lanes (&motion)[4]) {
  Lanes rows[4];
  for (int l = 0; l < 4; ++l) rows[l] = load(&batch.state[k + l]->position.x());
  transpose(rows, place);
  for (int l = 0; l < 4; ++l) rows[l] = load(&batch.state[k + l]->velocity.x());
  transpose(rows, motion);
}

/// Maps one separation component to its nearest image, as Domain::minimum_image.
CAROM_LANES_INLINE Lanes nearest_image(Lanes s, double length) {
  const Lanes half = splat(0.5 * length), l = splat(length);
  return select(s > half, s - l, select(s < -half, s + l, s));
}

template <bool kGravity, bool kImage>
CAROM_LANES_INLINE void contact_times_impl(const PairQuery& q, PairBatch& batch) {
  const Lanes clock_a = splat(q.clock);
  const Lanes pax = splat(q.position.x()), pay = splat(q.position.y()), paz = splat(q.position.z());
  const Lanes vax = splat(q.velocity.x()), vay = splat(q.velocity.y()), vaz = splat(q.velocity.z());
  const Lanes radius_a = splat(q.radius), zero = splat(0.0), never = splat(kNever);
  const Vec3 length = q.domain.length();
  // Each lane's earliest time and the first candidate that has it (k rises along a lane).
  Lanes earliest_time = never;
  Mask earliest = Mask{-1, -1, -1, -1};
  const Mask lane = Mask{0, 1, 2, 3};
  for (int k = 0; k < batch.count; k += 4) {
    // Candidate k + l's record is rows {position, clock} and {velocity, radius}.
    Lanes place[4], motion[4];
    load_records(batch, k, place, motion);
    const Lanes clock_b = place[3];
    const Lanes t_ref = select(clock_a > clock_b, clock_a, clock_b);
    const Lanes dt_a = t_ref - clock_a, dt_b = t_ref - clock_b;
    const Lanes vbx = motion[0], vby = motion[1], vbz = motion[2];
    Lanes dx = pax - place[0] + dt_a * vax - dt_b * vbx;
    Lanes dy = pay - place[1] + dt_a * vay - dt_b * vby;
    Lanes dz = paz - place[2] + dt_a * vaz - dt_b * vbz;
    Lanes ux = vax - vbx, uy = vay - vby, uz = vaz - vbz;
    if constexpr (kGravity) {
      const Lanes half = splat(0.5) * (dt_a * dt_a - dt_b * dt_b), lag = dt_a - dt_b;
      dx += half * splat(q.gravity.x());
      dy += half * splat(q.gravity.y());
      dz += half * splat(q.gravity.z());
      ux += lag * splat(q.gravity.x());
      uy += lag * splat(q.gravity.y());
      uz += lag * splat(q.gravity.z());
    }
    if constexpr (kImage) {
      if (q.domain.periodic[0]) dx = nearest_image(dx, length.x());
      if (q.domain.periodic[1]) dy = nearest_image(dy, length.y());
      if (q.domain.periodic[2]) dz = nearest_image(dz, length.z());
    }
    // sphere_contact_time, without branches.
    const Lanes contact = radius_a + motion[3];
    const Lanes b = dx * ux + dy * uy + dz * uz;
    const Lanes c = dx * dx + dy * dy + dz * dz - contact * contact;
    const Lanes v2 = ux * ux + uy * uy + uz * uz;
    const Lanes discriminant = b * b - v2 * c;
    Lanes root = select(discriminant > zero, discriminant, zero);
    for (int l = 0; l < 4; ++l) root[l] = std::sqrt(root[l]);
    const Lanes s = select(b >= zero, never,
                           select(c <= zero, zero,
                                  select(discriminant <= zero, never, c / (-b + root))));
    const Lanes t = t_ref + s;
    __builtin_memcpy(batch.time + k, &t, sizeof t);
    const Mask sooner = t < earliest_time;
    earliest_time = select(sooner, t, earliest_time);
    earliest = sooner ? lane + k : earliest;
  }
  // Across lanes: the least time, and of equal times the first candidate.
  int best = -1;
  double best_time = kNever;
  for (int l = 0; l < 4; ++l) {
    if (earliest[l] < 0) continue;
    if (earliest_time[l] < best_time || (earliest_time[l] == best_time && earliest[l] < best)) {
      best_time = earliest_time[l];
      best = static_cast<int>(earliest[l]);
    }
  }
  batch.earliest = best;
}

/// |x| in each lane (the same value as std::abs; -0 stays -0, which compares and adds as 0).
CAROM_LANES_INLINE Lanes magnitude(Lanes x) {
  return select(x < splat(0.0), -x, x);
}

template <bool kImage, bool kLines>
CAROM_LANES_INLINE std::uint64_t reach_tests_impl(const ReachQuery& q, const PairBatch& batch) {
  const Lanes pax = splat(q.position.x()), pay = splat(q.position.y()), paz = splat(q.position.z());
  const Lanes radius_a = splat(q.radius), sweep_a = splat(q.sweep), end = splat(q.end);
  const Lanes drive = splat(q.bounds.drive), rate = splat(q.bounds.rate), half = splat(0.5);
  const Lanes margin = splat(1.0 + 1e-12);
  // The line test's query.
  const Lanes vax = splat(q.velocity.x()), vay = splat(q.velocity.y()), vaz = splat(q.velocity.z());
  const Lanes clock_a = splat(q.clock), acceleration_a = splat(q.acceleration);
  const Lanes span_a = end - clock_a, line_margin = splat(1.0 + 1e-9), zero = splat(0.0);
  std::uint64_t reached = 0;
  const Vec3 length = q.domain.length();
  for (int k = 0; k < batch.count; k += 4) {
    Lanes place[4], motion[4];
    load_records(batch, k, place, motion);
    Lanes dx = pax - place[0], dy = pay - place[1], dz = paz - place[2];
    if constexpr (kImage) {
      if (q.domain.periodic[0]) dx = nearest_image(dx, length.x());
      if (q.domain.periodic[1]) dy = nearest_image(dy, length.y());
      if (q.domain.periodic[2]) dz = nearest_image(dz, length.z());
    }
    // may_reach's operations (with RelaxFlightBounds::reach_bound's) in their order.
    const Lanes span = end - place[3];
    const Lanes speed = magnitude(motion[0]) + magnitude(motion[1]) + magnitude(motion[2]);
    const Lanes sweep = span * (speed + half * span * (drive + rate * speed));
    const Lanes reach = (radius_a + motion[3] + sweep_a + sweep) * margin;
    Mask out = dx * dx + dy * dy + dz * dz > reach * reach;
    if constexpr (kLines) {
      // lines_apart's operations in their order.
      const Lanes clock_b = place[3];
      const Lanes t_ref = select(clock_a > clock_b, clock_a, clock_b);
      const Lanes dt_a = t_ref - clock_a, dt_b = t_ref - clock_b, horizon = end - t_ref;
      const Lanes vbx = motion[0], vby = motion[1], vbz = motion[2];
      Lanes lx = pax - place[0] + dt_a * vax - dt_b * vbx;
      Lanes ly = pay - place[1] + dt_a * vay - dt_b * vby;
      Lanes lz = paz - place[2] + dt_a * vaz - dt_b * vbz;
      if constexpr (kImage) {
        if (q.domain.periodic[0]) lx = nearest_image(lx, length.x());
        if (q.domain.periodic[1]) ly = nearest_image(ly, length.y());
        if (q.domain.periodic[2]) lz = nearest_image(lz, length.z());
      }
      const Lanes ux = vax - vbx, uy = vay - vby, uz = vaz - vbz;
      const Lanes acceleration_b = drive + rate * speed;
      const Lanes stray = half * (acceleration_a * span_a * span_a + acceleration_b * span * span);
      const Lanes line_reach = (radius_a + motion[3] + stray) * line_margin;
      const Lanes reach2 = line_reach * line_reach;
      const Lanes u2 = ux * ux + uy * uy + uz * uz, du = lx * ux + ly * uy + lz * uz;
      const Lanes ex = lx + horizon * ux, ey = ly + horizon * uy, ez = lz + horizon * uz;
      const Lanes cx = ly * uz - lz * uy, cy = lz * ux - lx * uz, cz = lx * uy - ly * ux;
      const Mask at_start = lx * lx + ly * ly + lz * lz > reach2;
      const Mask at_end = ex * ex + ey * ey + ez * ez > reach2;
      const Mask between = cx * cx + cy * cy + cz * cz > reach2 * u2;
      const Mask apart = du >= zero ? at_start : (-du >= horizon * u2 ? at_end : between);
      out |= apart;
    }
    for (int l = 0; l < 4; ++l) reached |= std::uint64_t(out[l] == 0) << (k + l);
  }
  return reached;
}
}  // namespace

#define CAROM_REACH_TESTS(I, L)                                                              \
  __attribute__((target_clones("avx2", "default"))) static std::uint64_t reach_tests_##I##L( \
      const ReachQuery& q, const PairBatch& batch) {                                         \
    return reach_tests_impl<I, L>(q, batch);                                                 \
  }                                                                                          \
  template <>                                                                                \
  std::uint64_t reach_tests<I, L>(const ReachQuery& q, const PairBatch& batch) {             \
    return reach_tests_##I##L(q, batch);                                                     \
  }

CAROM_REACH_TESTS(false, false)
CAROM_REACH_TESTS(true, false)
CAROM_REACH_TESTS(false, true)
CAROM_REACH_TESTS(true, true)

#undef CAROM_REACH_TESTS

#define CAROM_CONTACT_TIMES(G, I)                                                        \
  __attribute__((target_clones("avx2", "default"))) static void contact_times_##G##I( \
      const PairQuery& q, PairBatch& batch) {                                            \
    contact_times_impl<G, I>(q, batch);                                                  \
  }                                                                                      \
  template <>                                                                            \
  void contact_times<G, I>(const PairQuery& q, PairBatch& batch) {                       \
    contact_times_##G##I(q, batch);                                                      \
  }

CAROM_CONTACT_TIMES(false, false)
CAROM_CONTACT_TIMES(false, true)
CAROM_CONTACT_TIMES(true, false)
CAROM_CONTACT_TIMES(true, true)

#undef CAROM_CONTACT_TIMES
#undef CAROM_LANES_INLINE

}  // namespace carom
