#pragma once
/// The future-event calendar: a Boost.Heap mutable heap over small blocks of slots.
///
/// Slots 0..N-1 are particles (each holds its earliest predicted event); higher slots are
/// global events (end of run, samples, checkpoints). Ties in time are broken by the slot
/// number, so the order of events is a pure function of the predicted times: reproducible,
/// and the same after a checkpoint is restored.
///
/// Slots are grouped in blocks of kBlock consecutive slots. Each block keeps its earliest slot
/// (found by a scan of kBlock doubles, four cache lines), and the heap orders the blocks. The
/// heap is then kBlock times smaller, so it stays in cache: with one heap entry per slot, most
/// heap comparisons missed the L1 cache (cachegrind), and an update now often does not touch
/// the heap at all (when the block's earliest slot does not change). Blocks of 32 ran the dense
/// fluid (N = 32000, phi = 0.40) 1.07 times as fast as blocks of 16, and 64 1.04 times
/// (tests/bench/README.md, "The calendar's block size").
#include <algorithm>
#include <boost/heap/d_ary_heap.hpp>
#include <cstdint>
#include <vector>

#include "core/huge_pages.hpp"
#include "core/vec3.hpp"

namespace carom {

class Calendar {
 public:
  /// Slots per block.
  static constexpr std::size_t kBlock = 32;

  /// A calendar with `slots` entries, all at time kNever.
  explicit Calendar(std::size_t slots = 0) { resize(slots); }

  /// Grows to `slots` entries; new ones start at kNever.
  void resize(std::size_t slots) {
    slots_ = std::max(slots_, slots);
    const std::size_t blocks = (slots_ + kBlock - 1) / kBlock;
    times_.resize(blocks * kBlock, kNever);
    while (handles_.size() < blocks) {
      const auto block = static_cast<std::uint32_t>(handles_.size());
      handles_.push_back(heap_.push(Entry{kNever, block * static_cast<std::uint32_t>(kBlock)}));
    }
  }

  /// Sets the time of `slot`'s entry (earlier or later).
  void set(std::size_t slot, double time) {
    times_[slot] = time;
    const std::size_t block = slot / kBlock;
    const Entry current = *handles_[block];
    // The direction is known here, so the heap is told it (increase: towards the top) and
    // skips the comparison with the parent that a plain update makes first.
    if (time < current.time || (time == current.time && slot < current.slot)) {
      heap_.increase(handles_[block], Entry{time, static_cast<std::uint32_t>(slot)});
    } else if (slot == current.slot) {
      // The block's earliest entry got later (or stayed): look again; the block sinks.
      heap_.decrease(handles_[block], earliest_in(block));
    }
    // Otherwise a later entry than the block's earliest: nothing moves.
  }
  /// Sets slots 0..n-1 to time_of(0..n-1) (n <= size()), as n calls of set would, and then each
  /// block's place in the heap once: a block's entry is its earliest (time, slot) either way,
  /// so the top is the same. After a fluid step every particle is predicted again, and n sets
  /// scanned a block and moved the heap for most of them.
  template <class TimeOf>
  void set_first(std::size_t n, TimeOf&& time_of) {
    for (std::size_t s = 0; s < n; ++s) times_[s] = time_of(s);
    for (std::size_t block = 0; block * kBlock < n; ++block)
      heap_.update(handles_[block], earliest_in(block));
  }
  /// Starts loading what set(slot, ...) reads: the block's times (four cache lines) and its
  /// handle.
  void prefetch(std::size_t slot) const {
    const std::size_t block = slot / kBlock;
    const double* times = times_.data() + block * kBlock;
    for (std::size_t k = 0; k < kBlock; k += 8) __builtin_prefetch(times + k);
    __builtin_prefetch(handles_.data() + block);
  }
  /// The slot whose entry comes first.
  std::size_t top_slot() const { return heap_.top().slot; }
  /// The earliest time in the calendar, s.
  double top_time() const { return heap_.top().time; }
  /// The time now held by `slot`, s.
  double time_of(std::size_t slot) const { return times_[slot]; }
  std::size_t size() const { return slots_; }

 private:
  struct Entry {
    double time;
    std::uint32_t slot;
  };
  /// Max-heap comparator that puts the earliest (time, slot) on top.
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.time > b.time || (a.time == b.time && a.slot > b.slot);
    }
  };
  Entry earliest_in(std::size_t block) const {
    const std::size_t first = block * kBlock;
    std::size_t best = first;
    for (std::size_t s = first + 1; s < first + kBlock; ++s)
      if (times_[s] < times_[best]) best = s;
    return Entry{times_[best], static_cast<std::uint32_t>(best)};
  }
  using Heap = boost::heap::d_ary_heap<Entry, boost::heap::arity<4>, boost::heap::mutable_<true>,
                                       boost::heap::compare<Later>>;
  Heap heap_;
  std::vector<Heap::handle_type> handles_;  ///< One per block.
  BigVector<double> times_;                 ///< Per slot (padded to whole blocks with kNever).
  std::size_t slots_ = 0;
};

}  // namespace carom
