#pragma once
/// The candidates a particle's last prediction walked, kept as loading hints for its next one.
///
/// In a large system (from EventDrivenOptions::prefetch_from particles) each prediction waits on
/// a chain of cache misses: the particle's place, its cells' first particles, their list links,
/// the second places, and the candidates' records. The chain cannot start before the event is
/// known. But a particle's candidates change slowly (at phi = 0.40 it moves about a tenth of a
/// diameter between collisions and crosses a cell face once in four), so the candidates of its
/// last prediction are most of those of its next one, and their indices sit in one line whose
/// address is known from the particle alone. The engine keeps that line per particle (the first
/// kSize candidates of the own-level walk, in the walk's order) and, when the particle's event
/// comes to the top of the calendar, hints every remembered candidate's record, list link and
/// event counter into the L2 at once, one round trip instead of the chain. Kept for ballistic
/// flights on one grid level, where it measured 1.07-1.09 times the collisions per second at
/// N = 1e6, phi = 0.40 (tests/bench/README.md, "The candidates remembered"). Hints only: a stale
/// or short memo wastes loads and changes nothing computed.
///
/// The candidates are kept as 16-bit offsets from the particle's own index, so that one line
/// holds 31 of them, more than the about 20 of a block at phi = 0.40: the engine numbers the
/// particles in the order of their cells (z slowest), so a block's particles lie within a layer
/// of cells of the particle in index (about 9 000 at N = 1e6, 20 000 at 3e6). One whose offset
/// does not fit is kept as the particle itself, whose lines are loaded anyway. Fifteen 32-bit
/// indices (kSize was 15) left a quarter of each walk unhinted; the offsets ran N = 1e6 1.04 times
/// as fast once mixed and 1.06 in lattice order (tests/bench/README.md, "The memo as 16-bit
/// offsets").
#include <cstdint>

#include "events/event_driven/pair_batch.hpp"

namespace carom {

struct alignas(64) CandidateMemo {
  /// Candidates kept at most: with their count, one cache line of 16-bit offsets from the
  /// particle's own index (about 20 candidates a block at phi = 0.40; a fine among large spheres
  /// has 0-3 on its own level).
  static constexpr int kSize = 31;
  std::int16_t count = 0;        ///< Entries of offset in use.
  std::int16_t offset[kSize];    ///< candidate - self; 0 (self) where it does not fit 16 bits.

  /// A particle not yet predicted: nothing remembered.
  void reset() { count = 0; }
  /// The k-th remembered candidate of particle `self` (self itself for one whose offset did not
  /// fit).
  std::int32_t candidate(std::int32_t self, int k) const { return self + offset[k]; }
  /// The first kSize of the `found` (>= 1) candidates batch.state[0, found) (records of
  /// `records`) of particle `self`. Written without a branch on `found`: past it the last is
  /// repeated.
  void remember(std::int32_t self, const PairBatch& batch, int found, const PairState* records) {
    for (int k = 0; k < kSize; ++k) {
      const auto d = static_cast<std::int32_t>(batch.state[k < found ? k : found - 1] - records) - self;
      offset[k] = static_cast<std::int16_t>(d == static_cast<std::int16_t>(d) ? d : 0);
    }
    count = static_cast<std::int16_t>(found < kSize ? found : kSize);
  }
  /// Starts loading, into the L2 (`prefetcht1`, as the walk's own hints), what a walk over these
  /// candidates reads: their records, list links and event counters. Always inlined: GCC deems a
  /// function of prefetches alone free of effects and deletes calls to it.
  [[gnu::always_inline]] void hint(std::int32_t self, const PairState* records,
                                   const std::int32_t* next, const std::uint32_t* counters) const {
    records += self;
    next += self;
    counters += self;
    for (int c = 0; c < count; ++c) {
      const std::int32_t k = offset[c];
      __builtin_prefetch(records + k, 0, 2);
      __builtin_prefetch(next + k, 0, 2);
      __builtin_prefetch(counters + k, 0, 2);
    }
  }
};
static_assert(sizeof(CandidateMemo) == 64, "one cache line");

}  // namespace carom
