#pragma once
/// The live progress line of a long run: simulated time, events/s, collisions/s, ETA.
///
/// Drawn on stderr, rewritten in place at most a few times a second, only when stderr is a
/// terminal and the run is not --quiet (so logs and pipes stay clean).
#include <chrono>
#include <cstdint>

namespace carom {

class ProgressLine {
 public:
  /// `enabled` false: every call does nothing. `start_time`, `end_time`: simulated, s.
  ProgressLine(bool enabled, double start_time, double end_time);
  /// True when stderr is a terminal.
  static bool stderr_is_terminal();

  /// Reports the state after a chunk: simulated time (s), events and collisions so far.
  void update(double time, std::uint64_t events, std::uint64_t collisions);
  /// Ends the line (a newline), if anything was drawn.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool drawn_ = false;
  double start_time_, end_time_;
  Clock::time_point started_, last_draw_;
  std::uint64_t last_events_ = 0, last_collisions_ = 0;
  double last_time_ = 0;
  bool has_last_ = false;
  double events_rate_ = 0, collisions_rate_ = 0;
};

}  // namespace carom
