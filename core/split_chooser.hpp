#pragma once
/// Whether a pair of small tasks finishes sooner split between this thread and the side thread
/// (SideThread::run_beside) or one after the other here. It depends on the machine: a hand-over
/// moves a few cache lines between the two cores and back, 0.1 us a trip on some hosts and
/// 0.3 us on others (a task is 1-3 us), and on what else the other core is doing. So it is
/// measured as the run goes: a trial times both ways in alternating blocks of calls, the faster
/// is kept for the next many calls, and then a new trial looks again.
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
  /// Calls timed per trial: four blocks each way.
  static constexpr std::uint32_t kTrialCalls = 8 * kBlock;
  /// Calls between trials (a few tenths of a second of a dense bed's events).
  static constexpr std::uint32_t kKeptCalls = 32768;

  /// Runs split() or serial(), which must do the same work: timed while a trial lasts (the
  /// run starts with one), else the way the last trial found faster.
  template <class Split, class Serial>
  void run(Split&& split, Serial&& serial) {
    if (trial_left_ == 0) {
      if (split_)
        split();
      else
        serial();
      if (--kept_left_ == 0) {
        trial_left_ = kTrialCalls;
        spent_ = {};
      }
      return;
    }
    const bool splitting = ((kTrialCalls - trial_left_) / kBlock) % 2 == 0;
    const auto start = Clock::now();
    if (splitting)
      split();
    else
      serial();
    spent_[splitting] += Clock::now() - start;
    if (--trial_left_ == 0) {
      split_ = spent_[1] < spent_[0];  // a tie goes to one thread
      kept_left_ = kKeptCalls;
    }
  }

  /// The way kept since the last trial (false before the first trial has ended).
  bool splits() const { return split_; }
  /// Whether a trial is going on.
  bool in_trial() const { return trial_left_ > 0; }

 private:
  bool split_ = false;
  std::uint32_t trial_left_ = kTrialCalls;
  std::uint32_t kept_left_ = 0;
  std::array<typename Clock::duration, 2> spent_{};  ///< [serial, split] within the trial
};

}  // namespace carom
