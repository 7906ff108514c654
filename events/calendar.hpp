#pragma once
/// The future-event calendar: a Boost.Heap mutable heap with one entry per slot.
///
/// Slots 0..N-1 are particles (each holds its earliest predicted event); higher slots are
/// global events (end of run, samples, checkpoints). Ties in time are broken by the slot
/// number, so the order of events is a pure function of the predicted times: reproducible,
/// and the same after a checkpoint is restored.
#include <boost/heap/d_ary_heap.hpp>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"

namespace carom {

class Calendar {
 public:
  /// A calendar with `slots` entries, all at time kNever.
  explicit Calendar(std::size_t slots = 0) { resize(slots); }

  /// Grows to `slots` entries; new ones start at kNever.
  void resize(std::size_t slots) {
    handles_.reserve(slots);
    while (handles_.size() < slots) {
      const auto slot = static_cast<std::uint32_t>(handles_.size());
      handles_.push_back(heap_.push(Entry{kNever, slot}));
    }
  }
  /// Sets the time of `slot`'s entry (earlier or later).
  void set(std::size_t slot, double time) { heap_.update(handles_[slot], Entry{time, static_cast<std::uint32_t>(slot)}); }
  /// The slot whose entry comes first.
  std::size_t top_slot() const { return heap_.top().slot; }
  /// The earliest time in the calendar, s.
  double top_time() const { return heap_.top().time; }
  /// The time now held by `slot`, s.
  double time_of(std::size_t slot) const { return (*handles_[slot]).time; }
  std::size_t size() const { return handles_.size(); }

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
  using Heap = boost::heap::d_ary_heap<Entry, boost::heap::arity<8>, boost::heap::mutable_<true>,
                                       boost::heap::compare<Later>>;
  Heap heap_;
  std::vector<Heap::handle_type> handles_;
};

}  // namespace carom
