#pragma once
/// The progress of a long run on stderr: simulated time, events/s, collisions/s, ETA.
///
/// On a terminal one line is rewritten in place at most four times a second. When stderr is a
/// file, a pipe or a batch system's log, a whole line is written every kProgressLogInterval
/// seconds of wall time instead (nothing for runs shorter than that). Nothing with --quiet.
#include <chrono>
#include <cstdint>

namespace carom {

/// Wall seconds between two progress lines written to a log (stderr not a terminal).
inline constexpr double kProgressLogInterval = 30.0;

class ProgressLine {
 public:
  /// `enabled` false: every call does nothing. `start_time`, `end_time`: simulated, s. Whether
  /// stderr is a terminal decides between the rewritten line and the log lines.
  /// `log_interval`: wall seconds between log lines.
  ProgressLine(bool enabled, double start_time, double end_time, double log_interval = kProgressLogInterval);
  /// True when stderr is a terminal.
  static bool stderr_is_terminal();

  /// Reports the state after a chunk: simulated time (s), events and collisions so far.
  void update(double time, std::uint64_t events, std::uint64_t collisions);
  /// Ends the line (a newline), if anything was drawn.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool terminal_;  ///< stderr is a terminal: one line rewritten in place.
  double log_interval_;
  bool drawn_ = false;
  double start_time_, end_time_;
  Clock::time_point started_, last_draw_;
  std::uint64_t last_events_ = 0, last_collisions_ = 0;
  double last_time_ = 0;
  bool has_last_ = false;
  bool counted_ = false;  ///< last_events_ and last_collisions_ hold a count.
  double events_rate_ = 0, collisions_rate_ = 0;
};

}  // namespace carom
