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
#include <cstdint>

#include "events/event_driven/pair_batch.hpp"

namespace carom {

struct alignas(64) CandidateMemo {
  /// Candidates kept at most: with their count, one cache line (about 20 candidates a block at
  /// phi = 0.40; a fine among large spheres has 0-3 on its own level).
  static constexpr int kSize = 15;
  std::int32_t count = 0;  ///< Entries of id in use.
  std::int32_t id[kSize];

  /// A particle not yet predicted: nothing remembered.
  void reset() { count = 0; }
  /// The first kSize of the `found` (>= 1) candidates batch.state[0, found) (records of
  /// `records`). Written without a branch on `found`: past it the last is repeated.
  void remember(const PairBatch& batch, int found, const PairState* records) {
    for (int k = 0; k < kSize; ++k)
      id[k] = static_cast<std::int32_t>(batch.state[k < found ? k : found - 1] - records);
    count = found < kSize ? found : kSize;
  }
  /// Starts loading, into the L2 (`prefetcht1`, as the walk's own hints), what a walk over these
  /// candidates reads: their records, list links and event counters. Always inlined: GCC deems a
  /// function of prefetches alone free of effects and deletes calls to it.
  [[gnu::always_inline]] void hint(const PairState* records, const std::int32_t* next,
                                   const std::uint32_t* counters) const {
    for (int c = 0; c < count; ++c) {
      const std::int32_t k = id[c];
      __builtin_prefetch(records + k, 0, 2);
      __builtin_prefetch(next + k, 0, 2);
      __builtin_prefetch(counters + k, 0, 2);
    }
  }
};
static_assert(sizeof(CandidateMemo) == 64, "one cache line");

}  // namespace carom
