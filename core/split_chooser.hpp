#pragma once
/// Whether a pair of small tasks is better split between this thread and the side thread
/// (SideThread::run_beside) or run one after the other here. It depends on the machine: a
/// hand-over moves a few cache lines between the two cores and back, 0.1 us a trip on some hosts
/// and 0.3 us on others (a task is 1-3 us), and the lines the side thread touched are missing
/// from this core's cache afterwards; and on what else the other core is doing. So it is
/// measured as the run goes: a trial alternates the two ways in blocks of calls and times each
/// block from its first call to the next block's first call (the calls and all the work between
/// them, where the cache misses a split leaves behind are paid), the faster way is kept for the
/// next many calls, and then a new trial looks again.
///
/// Both ways must give the same result (they differ only in which thread runs a task): the
/// choice changes the speed, never the run.
#include <array>
#include <chrono>
#include <cstdint>

namespace carom {

template <class Clock = std::chrono::steady_clock>
class SplitChooser {
 public:
  /// Calls per block of a trial (the two ways alternate block by block, so that a change of the
  /// machine's pace within a trial hits both).
  static constexpr std::uint32_t kBlock = 64;
  /// Blocks per trial: four each way.
  static constexpr std::uint32_t kTrialBlocks = 8;
  /// Calls per trial.
  static constexpr std::uint32_t kTrialCalls = kTrialBlocks * kBlock;
  /// Calls between trials (a few tenths of a second of a dense bed's events).
  static constexpr std::uint32_t kKeptCalls = 32768;

  /// Runs split() or serial(), which must do the same work: the way of its block while a trial
  /// lasts (the run starts with one), else the way the last trial found faster.
  template <class Split, class Serial>
  void run(Split&& split, Serial&& serial) {
    if (in_trial_ && trial_call_ % kBlock == 0) turn_block();
    const bool splitting = in_trial_ ? (trial_call_ / kBlock) % 2 == 0 : split_;
    if (splitting)
      split();
    else
      serial();
    if (in_trial_)
      ++trial_call_;
    else if (--kept_left_ == 0)
      start_trial();
  }

  /// Says that other work than the calls' (a fluid step, output between runs) came since the
  /// last call: the block under way is left out of the trial's times.
  void interrupt() { interrupted_ = true; }

  /// The way kept since the last trial (false before the first trial has ended).
  bool splits() const { return split_; }
  /// Whether a trial is going on (its last block is booked at the first call after it).
  bool in_trial() const { return in_trial_; }

 private:
  /// At the first call of a block: books the block that ends here, and ends the trial after its
  /// last block.
  void turn_block() {
    const auto now = Clock::now();
    if (trial_call_ > 0 && !interrupted_) {
      const bool splitting = ((trial_call_ / kBlock - 1) % 2) == 0;
      spent_[splitting] += now - block_start_;
      ++timed_[splitting];
    }
    block_start_ = now;
    interrupted_ = false;
    if (trial_call_ == kTrialCalls) {
      // The mean block of each way; one that was never timed leaves the choice as it was.
      if (timed_[0] > 0 && timed_[1] > 0)
        split_ = spent_[1] * timed_[0] < spent_[0] * timed_[1];  // a tie goes to one thread
      in_trial_ = false;
      kept_left_ = kKeptCalls;
    }
  }
  void start_trial() {
    in_trial_ = true;
    trial_call_ = 0;
    spent_ = {};
    timed_ = {};
  }

  bool split_ = false;
  bool in_trial_ = true;
  bool interrupted_ = false;
  std::uint32_t trial_call_ = 0;  ///< calls made in the trial
  std::uint32_t kept_left_ = 0;
  typename Clock::time_point block_start_{};
  std::array<typename Clock::duration, 2> spent_{};  ///< [serial, split]: timed blocks' time
  std::array<std::uint32_t, 2> timed_{};             ///< [serial, split]: blocks timed
};

}  // namespace carom
