// The calendar's buckets: taking the next one, the blocks beyond the ring, the width.
#include "events/event_driven/calendar.hpp"

#include <algorithm>

namespace carom {

void Calendar::resize(std::size_t slots) {
  slots_ = std::max(slots_, slots);
  const std::size_t blocks = (slots_ + kBlock - 1) / kBlock;
  times_.resize(blocks * kBlock, kNever);
  for (std::size_t block = blocks_.size(); block < blocks; ++block)
    blocks_.push_back(Block{Entry{kNever, static_cast<std::uint32_t>(block * kBlock)}, kNeverFiled, {}});
}

void Calendar::refile_far() {
  std::size_t kept = 0;
  far_first_ = kNeverFiled;
  for (const auto& [block, k] : far_) {
    if (blocks_[block].filed != k) continue;  // stale: the block was filed again since
    if (k <= current_) {  // the current bucket: into the heap with the ring's entries
      enter_heap(block);
      ++entered_;
      continue;
    }
    // The current bucket's place in the ring is also that of bucket current_ + ring_reach(),
    // and its entries are taken after this: that bucket stays far until the next one.
    if (k - current_ < ring_reach() && into_ring(block, k)) continue;
    far_[kept++] = {block, k};
    far_first_ = std::min(far_first_, k);
  }
  far_.resize(kept);
}

void Calendar::refill() {
  while (heap_.empty()) {
    if (ring_entries_ == 0) {
      if (far_.empty()) return;  // every time is kNever
      current_ = std::max(current_, far_first_ - 1);  // no block is filed before far_first_
    }
    ++current_;
    if (far_first_ - current_ < ring_reach()) refile_far();
    const std::size_t place = ring_place(current_);
    const std::uint32_t* entries = ring_.data() + place * kBucketEntries;
    const std::uint32_t n = ring_count_[place];
    ring_entries_ -= n;
    ring_count_[place] = 0;
    // The entries' blocks lie anywhere: their loads are started together, not one by one.
    for (std::uint32_t e = 0; e < n; ++e) __builtin_prefetch(blocks_.data() + entries[e]);
    std::size_t entered = 0;
    for (std::uint32_t e = 0; e < n; ++e) {
      if (blocks_[entries[e]].filed != current_) continue;  // stale, or a second entry taken
      enter_heap(entries[e]);
      ++entered;
    }
    entered_ += entered;
    if (++buckets_used_ == kTuneEvery) {
      // The width again where the buckets brought far more or far fewer blocks than asked.
      const double per_bucket = static_cast<double>(entered_) / kTuneEvery;
      if (per_bucket < kPerBucket / 2 || per_bucket > kPerBucket * 2)
        retune_ = kPerBucket / std::max(per_bucket, 1.0) / inverse_width_;
      entered_ = 0;
      buckets_used_ = 0;
    }
  }
}

void Calendar::tune(double width) {
  std::vector<double> first;
  for (const Block& b : blocks_)
    if (b.least.time != kNever) first.push_back(b.least.time);
  inverse_width_ = 0;
  origin_ = 0;
  retune_ = 0;
  std::size_t buckets = 1;
  if (first.size() >= kBucketFrom) {
    const auto rank = static_cast<std::size_t>(8 * kPerBucket);
    const auto at_rank = first.begin() + static_cast<std::ptrdiff_t>(rank);
    std::nth_element(first.begin(), at_rank, first.end());
    const double earliest = *std::min_element(first.begin(), at_rank);
    if (width == 0) width = (*at_rank - earliest) * kPerBucket / static_cast<double>(rank);
    if (width > 0 && std::isfinite(width) && std::isfinite(1 / width)) {
      origin_ = earliest;
      inverse_width_ = 1 / width;
      // The ring spans about eight times the blocks' spread if their times were spread as
      // evenly as the first ones; later blocks wait beyond it.
      while (buckets < 8 * first.size() / static_cast<std::size_t>(kPerBucket)) buckets *= 2;
    }
  }
  heap_.clear();
  ring_count_.assign(buckets, 0);
  ring_.resize(buckets * kBucketEntries);
  far_.clear();
  far_first_ = kNeverFiled;
  ring_entries_ = 0;
  current_ = 0;
  for (std::size_t block = 0; block < blocks_.size(); ++block) {
    const std::int64_t k = bucket_of(blocks_[block].least.time);
    if (k <= current_)
      enter_heap(block);
    else
      file_later(block, k);
  }
  refill();
  ++tunings_;
  sets_since_tuned_ = 0;
  entered_ = 0;
  buckets_used_ = 0;
}

bool Calendar::consistent() const {
  std::size_t in_heap = 0;
  for (std::size_t block = 0; block < blocks_.size(); ++block) {
    const Block& b = blocks_[block];
    const Entry e = earliest_in(block);
    if (e.time != b.least.time || e.slot != b.least.slot) return false;
    const std::int64_t k = bucket_of(e.time);
    if (k <= current_) {
      if (b.filed != kInHeap) return false;
      const Entry h = *b.handle;
      if (h.time != e.time || h.slot != e.slot) return false;
      ++in_heap;
      continue;
    }
    if (b.filed != k) return false;
    if (k == kNeverFiled) continue;
    // Among its bucket's entries in the ring, or beyond it (where the ring does not reach the
    // bucket yet, or its place was full).
    const auto id = static_cast<std::uint32_t>(block);
    const bool in_far = std::count(far_.begin(), far_.end(), std::pair{id, k}) > 0;
    bool in_ring = false;
    if (k - current_ <= ring_reach()) {
      const std::uint32_t* entries = ring_.data() + ring_place(k) * kBucketEntries;
      in_ring = std::count(entries, entries + ring_count_[ring_place(k)], id) > 0;
    }
    if (!in_ring && !in_far) return false;
  }
  return in_heap == heap_.size();
}

}  // namespace carom
