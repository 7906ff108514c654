#pragma once
/// The future-event calendar: blocks of slots, the near ones ordered by a Boost.Heap mutable
/// heap, the later ones waiting in time buckets (a calendar queue over blocks).
///
/// Slots 0..N-1 are particles (each holds its earliest predicted event); higher slots are
/// global events (end of run, samples, checkpoints). Ties in time are broken by the slot
/// number, so the order of events is a pure function of the predicted times: reproducible,
/// and the same after a checkpoint is restored.
///
/// Slots are grouped in blocks of kBlock consecutive slots. Each block keeps its earliest slot
/// (found by a scan of kBlock doubles, four cache lines), and only blocks are ordered: with one
/// heap entry per slot, most heap comparisons missed the L1 cache (cachegrind), and an update
/// often moves nothing (when the block's earliest slot does not change). Blocks of 32 ran the
/// dense fluid (N = 32000, phi = 0.40) 1.07 times as fast as blocks of 16, and 64 1.04 times
/// (tests/bench/README.md, "The calendar's block size").
///
/// In small calendars every block with a finite time is in the heap. From kBucketFrom such
/// blocks on, the time axis is cut into buckets of equal width (Brown's calendar queue, which
/// Paul 2007 uses for event-driven hard spheres; here over blocks): the heap holds only the
/// blocks whose earliest time falls in the current bucket or before it, and every later block
/// waits in its bucket until the current bucket has been used up. A popped block's next time
/// is usually far ahead: in a heap of all 31 250 blocks of a million particles it sank through
/// eight levels, each a load of four children's nodes that missed the caches; now it is filed
/// in its bucket by one store. A block that changes bucket leaves its old entry behind, stale;
/// each entry is checked against the block's filing when its bucket is reached. The bucket
/// index is a monotone function of the time, so every block in the heap comes before every
/// waiting one and the heap's top is the calendar's top: the order of events is the same as a
/// plain heap's whatever the width (the tests compare it with a linear scan and an ordered
/// set), and the width is tuned for speed alone.
#include <boost/heap/d_ary_heap.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/huge_pages.hpp"
#include "core/vec3.hpp"

namespace carom {

class Calendar {
 public:
  /// Slots per block.
  static constexpr std::size_t kBlock = 32;
  /// Blocks with finite times from which later blocks wait in buckets (below it the heap of all
  /// of them stays in the L1 and L2 caches).
  static constexpr std::size_t kBucketFrom = 2048;
  /// About how many blocks each bucket brings into the heap (the width is tuned for it).
  static constexpr double kPerBucket = 32;
  /// Entries a bucket holds in the ring (stale ones included); more wait beyond the ring.
  static constexpr std::size_t kBucketEntries = 64;
  /// Buckets between looks at how many blocks they brought.
  static constexpr std::size_t kTuneEvery = 256;

  /// A calendar with `slots` entries, all at time kNever.
  explicit Calendar(std::size_t slots = 0) { resize(slots); }

  /// Grows to `slots` entries; new ones start at kNever.
  void resize(std::size_t slots);

  /// Sets the time of `slot`'s entry (earlier or later).
  void set(std::size_t slot, double time) {
    times_[slot] = time;
    const std::size_t block = slot / kBlock;
    const Entry current = blocks_[block].least;
    if (time < current.time || (time == current.time && slot < current.slot)) {
      blocks_[block].least = Entry{time, static_cast<std::uint32_t>(slot)};
      moved_earlier(block);
    } else if (slot == current.slot) {
      // The block's earliest entry got later (or stayed): look again.
      blocks_[block].least = earliest_in(block);
      moved_later(block);
    }
    // Otherwise a later entry than the block's earliest: nothing moves.
    if (retune_ > 0) {
      tune(retune_);
    } else if (!bucketed() && heap_.size() >= kBucketFrom &&
               ++sets_since_tuned_ > 4 * blocks_.size()) {
      tune();
    }
  }
  /// Sets slots 0..n-1 to time_of(0..n-1) (n <= size()), as n calls of set would, and then
  /// files every block once: the calendar's top is the same. After a fluid step every particle
  /// is predicted again, and n sets scanned a block and moved the heap for most of them.
  template <class TimeOf>
  void set_first(std::size_t n, TimeOf&& time_of) {
    for (std::size_t s = 0; s < n; ++s) times_[s] = time_of(s);
    for (std::size_t block = 0; block * kBlock < n; ++block)
      blocks_[block].least = earliest_in(block);
    tune();
  }
  /// Starts loading what set(slot, ...) reads: the block's times (four cache lines) and its
  /// earliest entry, filing and heap handle (half a line).
  void prefetch(std::size_t slot) const {
    const std::size_t block = slot / kBlock;
    const double* times = times_.data() + block * kBlock;
    for (std::size_t k = 0; k < kBlock; k += 8) __builtin_prefetch(times + k);
    __builtin_prefetch(blocks_.data() + block);
  }
  /// The slot whose entry comes first (slot 0 when every time is kNever).
  std::size_t top_slot() const { return heap_.empty() ? 0 : heap_.top().slot; }
  /// The earliest time in the calendar, s.
  double top_time() const { return heap_.empty() ? kNever : heap_.top().time; }
  /// The time now held by `slot`, s.
  double time_of(std::size_t slot) const { return times_[slot]; }
  std::size_t size() const { return slots_; }

  /// Whether later blocks wait in buckets now (for the tests; the order is the same either way).
  bool bucketed() const { return inverse_width_ > 0; }
  /// How often the width has been chosen (for the tests).
  std::size_t tunings() const { return tunings_; }
  /// Whether every block is filed where its earliest time says (for the tests; O(slots)): in
  /// the heap with that entry up to the current bucket, else waiting among its bucket's entries
  /// or beyond the ring, or never.
  bool consistent() const;

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
  using Heap = boost::heap::d_ary_heap<Entry, boost::heap::arity<4>, boost::heap::mutable_<true>,
                                       boost::heap::compare<Later>>;
  /// A block's filing: in the heap, waiting in bucket k (> current_), or never (all kNever).
  static constexpr std::int64_t kInHeap = std::numeric_limits<std::int64_t>::min();
  static constexpr std::int64_t kNeverFiled = std::numeric_limits<std::int64_t>::max();
  /// Bucket indices of finite times are clamped to +-kFarthest.
  static constexpr std::int64_t kFarthest = std::int64_t{1} << 60;
  /// What the calendar keeps of a block, in half a cache line.
  struct alignas(32) Block {
    Entry least;               ///< Its earliest (time, slot).
    std::int64_t filed;        ///< kInHeap, its bucket, or kNeverFiled.
    Heap::handle_type handle;  ///< Its place in heap_ (while filed kInHeap).
  };
  static_assert(sizeof(Block) == 32, "half a cache line");

  Entry earliest_in(std::size_t block) const {
    const std::size_t first = block * kBlock;
    std::size_t best = first;
    for (std::size_t s = first + 1; s < first + kBlock; ++s)
      if (times_[s] < times_[best]) best = s;
    return Entry{times_[best], static_cast<std::uint32_t>(best)};
  }
  /// The bucket of time t: monotone in t (a later time never gets an earlier bucket), 0 for
  /// every finite time while the calendar is not bucketed.
  std::int64_t bucket_of(double t) const {
    if (t == kNever) return kNeverFiled;
    const double x = std::floor((t - origin_) * inverse_width_);
    if (!(x < static_cast<double>(kFarthest))) return kFarthest;
    if (!(x > -static_cast<double>(kFarthest))) return -kFarthest;
    return static_cast<std::int64_t>(x);
  }
  std::int64_t ring_reach() const { return static_cast<std::int64_t>(ring_count_.size()); }
  std::size_t ring_place(std::int64_t k) const {
    return static_cast<std::size_t>(k) & (ring_count_.size() - 1);
  }

  /// The block's earliest entry got earlier.
  void moved_earlier(std::size_t block) {
    Block& b = blocks_[block];
    if (b.filed == kInHeap) {
      heap_.increase(b.handle, b.least);  // towards the top
      return;
    }
    const std::int64_t k = bucket_of(b.least.time);
    if (k <= current_) {
      enter_heap(block);
    } else if (k != b.filed) {
      file_later(block, k);
    }
  }
  /// The block's earliest entry got later (or stayed).
  void moved_later(std::size_t block) {
    Block& b = blocks_[block];
    const std::int64_t k = bucket_of(b.least.time);
    if (b.filed == kInHeap) {
      if (k <= current_) {
        heap_.decrease(b.handle, b.least);  // the block sinks
        return;
      }
      heap_.erase(b.handle);
      file_later(block, k);
      if (heap_.empty()) refill();
    } else if (k != b.filed) {
      file_later(block, k);
    }
  }
  /// Files a block that is not in the heap under bucket k > current_ (or as never): among the
  /// ring's entries of bucket k while the ring reaches it and it has room, else beyond the ring.
  void file_later(std::size_t block, std::int64_t k) {
    blocks_[block].filed = k;
    if (k == kNeverFiled) return;
    if (k - current_ <= ring_reach() && into_ring(static_cast<std::uint32_t>(block), k)) return;
    far_.emplace_back(static_cast<std::uint32_t>(block), k);
    far_first_ = std::min(far_first_, k);
  }
  /// Adds the block to bucket k's entries in the ring (which reaches k), if its place has room.
  bool into_ring(std::uint32_t block, std::int64_t k) {
    const std::size_t place = ring_place(k);
    const std::uint32_t n = ring_count_[place];
    if (n == kBucketEntries) return false;
    ring_[place * kBucketEntries + n] = block;
    ring_count_[place] = n + 1;
    ++ring_entries_;
    return true;
  }
  /// Puts a block that is not in the heap there, with its earliest entry.
  void enter_heap(std::size_t block) {
    blocks_[block].handle = heap_.push(blocks_[block].least);
    blocks_[block].filed = kInHeap;
  }
  /// Takes the next buckets until the heap holds a block (or every block is never).
  void refill();
  /// Files the far blocks whose bucket the ring now reaches among its entries (into the heap
  /// for the current bucket); drops stale entries.
  void refile_far();
  /// Chooses the bucket width (`width` s, or where it is 0 from the blocks' earliest times:
  /// about kPerBucket blocks in each of the first buckets) and files every block again; not
  /// bucketed below kBucketFrom blocks with finite times, or where the first times are all
  /// equal.
  void tune(double width = 0);

  Heap heap_;                ///< The blocks filed kInHeap.
  BigVector<double> times_;  ///< Per slot (padded to whole blocks with kNever).
  BigVector<Block> blocks_;
  /// Buckets current_ + 1 .. current_ + ring_reach(), bucket k at place k mod ring_reach():
  /// kBucketEntries blocks a place (filed there, or stale: filed elsewhere since), of which
  /// ring_count_ are in use.
  BigVector<std::uint32_t> ring_;
  std::vector<std::uint32_t> ring_count_ = std::vector<std::uint32_t>(1, 0);
  std::vector<std::pair<std::uint32_t, std::int64_t>> far_;  ///< Blocks beyond the ring.
  std::int64_t far_first_ = kNeverFiled;  ///< No far block is filed before this bucket.
  std::size_t ring_entries_ = 0;          ///< Entries in the ring, stale ones included.
  std::int64_t current_ = 0;              ///< The heap holds every block filed up to here.
  double origin_ = 0;                     ///< Bucket 0 starts here, s.
  double inverse_width_ = 0;              ///< 1 / the buckets' width, 1/s; 0: not bucketed.
  std::size_t sets_since_tuned_ = 0;      ///< While not bucketed: sets since the last try.
  std::size_t entered_ = 0;       ///< Blocks brought into the heap by the last buckets.
  std::size_t buckets_used_ = 0;  ///< Buckets taken since the last look at the width.
  double retune_ = 0;             ///< > 0: the width to take at the end of this set, s.
  std::size_t tunings_ = 0;
  std::size_t slots_ = 0;
};

}  // namespace carom
