#include "scenarios/run/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace carom {

ProgressLine::ProgressLine(bool enabled, double start_time, double end_time, double log_interval)
    : enabled_(enabled), terminal_(stderr_is_terminal()), log_interval_(log_interval), start_time_(start_time), end_time_(end_time), started_(Clock::now()), last_draw_(started_) {}

bool ProgressLine::stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

namespace {
std::string duration_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  char buffer[32];
  const long s = std::lround(seconds);
  if (s >= 3600) std::snprintf(buffer, sizeof(buffer), "%ldh%02ldm", s / 3600, (s / 60) % 60);
  else if (s >= 60) std::snprintf(buffer, sizeof(buffer), "%ldm%02lds", s / 60, s % 60);
  else std::snprintf(buffer, sizeof(buffer), "%lds", s);
  return buffer;
}
}  // namespace

void ProgressLine::update(double time, std::uint64_t events, std::uint64_t collisions) {
  if (!enabled_) return;
  if (!counted_) {  // the counts at this run's (or resume's) first chunk: the rates' baseline
    last_events_ = events;
    last_collisions_ = collisions;
    counted_ = true;
  }
  const auto now = Clock::now();
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  // The first log line comes after one interval too: a short run writes none.
  if (terminal_ ? has_last_ && since_draw < 0.25 : since_draw < log_interval_) return;
  // Rates since the last line; a log's first line counts from this run's (or resume's) first chunk.
  if ((has_last_ || !terminal_) && since_draw > 0) {
    events_rate_ = static_cast<double>(events - last_events_) / since_draw;
    collisions_rate_ = static_cast<double>(collisions - last_collisions_) / since_draw;
  }
  const double elapsed = std::chrono::duration<double>(now - started_).count();
  const double done = (time - start_time_) / (end_time_ - start_time_);
  const double eta = done > 0 ? elapsed * (1.0 - done) / done : NAN;
  if (!terminal_) {
    std::fprintf(stderr, "carom: t = %.4g / %.4g s (%.1f%%), %.3g events/s, %.3g collisions/s, %s of wall time, "
                 "about %s to go\n", time, end_time_, 100.0 * done, events_rate_, collisions_rate_,
                 duration_text(elapsed).c_str(), duration_text(eta).c_str());
  } else {
    std::fprintf(stderr, "\r  t = %.4g / %.4g s (%5.1f%%)  %.3g events/s  %.3g collisions/s  ETA %s   ", time,
                 end_time_, 100.0 * done, events_rate_, collisions_rate_, duration_text(eta).c_str());
  }
  std::fflush(stderr);
  drawn_ = true;
  has_last_ = true;
  last_draw_ = now;
  last_events_ = events;
  last_collisions_ = collisions;
  last_time_ = time;
}

void ProgressLine::finish() {
  if (enabled_ && terminal_ && drawn_) std::fputc('\n', stderr);
  drawn_ = false;
}

}  // namespace carom
