#include "scenarios/run/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace carom {

ProgressLine::ProgressLine(bool enabled, double start_time, double end_time)
    : enabled_(enabled), start_time_(start_time), end_time_(end_time), started_(Clock::now()), last_draw_(started_) {}

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
  const auto now = Clock::now();
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  if (has_last_ && since_draw < 0.25) return;
  if (has_last_ && since_draw > 0) {
    events_rate_ = static_cast<double>(events - last_events_) / since_draw;
    collisions_rate_ = static_cast<double>(collisions - last_collisions_) / since_draw;
  }
  const double elapsed = std::chrono::duration<double>(now - started_).count();
  const double done = (time - start_time_) / (end_time_ - start_time_);
  const double eta = done > 0 ? elapsed * (1.0 - done) / done : NAN;
  std::fprintf(stderr, "\r  t = %.4g / %.4g s (%5.1f%%)  %.3g events/s  %.3g collisions/s  ETA %s   ", time,
               end_time_, 100.0 * done, events_rate_, collisions_rate_, duration_text(eta).c_str());
  std::fflush(stderr);
  drawn_ = true;
  has_last_ = true;
  last_draw_ = now;
  last_events_ = events;
  last_collisions_ = collisions;
  last_time_ = time;
}

void ProgressLine::finish() {
  if (enabled_ && drawn_) std::fputc('\n', stderr);
  drawn_ = false;
}

}  // namespace carom
