#pragma once
/// The collapse detector of the event-driven engine (core/DESIGN.md, "Collision laws and
/// collapse"): inelastic collapse (infinitely many collisions in finite time) or particles resting
/// in lasting contact make the event rate diverge; the detector stops such a run with a diagnostic
/// instead of letting it hang.
#include <cstdint>
#include <string>

#include "core/vec3.hpp"
#include "events/laws/collapse.hpp"

namespace carom {

/// One particle's count of collisions in its current stall window (kept in its agenda record).
struct StallRecord {
  double window_start = -kNever;  ///< Start of the window, s.
  std::uint32_t count = 0;        ///< Collisions in that window.
};

/// Two tests: one particle takes part in more than `limit` collisions within `window`
/// seconds of simulated time; or more than 10^6 + 100 N events in a row do not move time on.
struct StallDetector {
  double window = 0;          ///< Simulated window of the per-particle count, s.
  std::uint64_t limit = 1000; ///< Collisions a particle may take part in within one window.
  std::uint64_t events_without_progress = 0;  ///< Consecutive events at one time.

  /// The window of `options`, or (when it is <= 0) 1e-9 of the collision time scale: the
  /// smallest diameter d_min over max(rms speed, sqrt(|g| d_min)).
  static double default_window(const CollapseOptions& options, double smallest_diameter,
                               double rms_speed, double gravity);

  /// Books one collision of a particle at time t (s) into its record; true when the particle
  /// has now taken part in more than `limit` collisions within one window.
  bool book(StallRecord& record, double t) const {
    if (t - record.window_start > window) {
      record.window_start = t;
      record.count = 1;
      return false;
    }
    return ++record.count > limit;
  }
  /// Books a particle event at time t (s), `last` the time of the previous one; true when more
  /// than 10^6 + 100 `particles` events in a row have not moved time on.
  bool stuck(double t, double last, std::size_t particles) {
    if (t > last) {
      events_without_progress = 0;
      return false;
    }
    return ++events_without_progress > 1000000 + 100 * particles;
  }
};

/// The third test, lasting contacts: the collision frequency per particle, averaged over all
/// particles over a window of at least `window` collisions (pair and wall events) and at least
/// `min_span` seconds, above `limit`. Hard spheres in lasting contact (a packed bed under the TC
/// model, a plug pinned under a lid) collide ever faster as their gaps close; no per-particle
/// window catches that while time still moves on.
struct RateMonitor {
  double limit = 0;                  ///< Collisions per particle per second; 0: off.
  std::uint64_t window = 0;          ///< Collision events per measurement, at least.
  /// Simulated time per measurement, at least, s: 5000 / limit, 100 contact times at the default
  /// (a packed bed rattles in bursts: over 2.5e-5 s its frequency reached 17 times its 5 ms mean).
  double min_span = 0;
  std::uint64_t start_pairs = 0;     ///< Pair collisions at the window's start.
  std::uint64_t start_walls = 0;     ///< Wall collisions at the window's start.
  double start_time = 0;             ///< s.

  /// Whether a measurement is due after `pairs` + `walls` collision events, at time t (s).
  bool due(std::uint64_t pairs, std::uint64_t walls, double t) const {
    return limit > 0.0 && pairs + walls - start_pairs - start_walls >= window && t - start_time >= min_span;
  }
  /// The mean collision frequency per particle of `particles` over the window ending at time t
  /// (s) with these counts, 1/s; starts the next window.
  double measure(std::uint64_t pairs, std::uint64_t walls, double t, std::size_t particles) {
    const double collisions = 2.0 * double(pairs - start_pairs) + double(walls - start_walls);
    const double span = t - start_time;
    start_pairs = pairs;
    start_walls = walls;
    start_time = t;
    // A window without time moving on is the stuck test's case (StallDetector::stuck).
    return span > 0.0 ? collisions / (double(particles) * span) : 0.0;
  }
};

/// The diagnostic of a run caught by RateMonitor: the measured frequency, the limit and where it
/// comes from, and the remedies.
std::string lasting_contact_diagnostic(double t, double frequency, double span,
                                       const CollapseOptions& options);

/// The remedies for a run caught by the stall detector, as they apply to `options`: the TC
/// model and the low-speed rule are advised only where they are off (where they are on, what
/// changing their setting does), then the restitution and the soft-sphere method.
std::string collapse_remedy(const CollapseOptions& options);
/// The diagnostic of a particle caught by StallDetector::book: who, where, with whom, and the
/// remedies. `particle`, `partner`: descriptions ("particle 12 (species glass, at x y z m)").
std::string collapse_diagnostic(double t, const std::string& particle, std::uint32_t count,
                                double window, const std::string& partner,
                                const CollapseOptions& options);
/// The diagnostic of a run caught by StallDetector::stuck.
std::string stuck_diagnostic(double t, std::uint64_t events, const std::string& particle,
                             const CollapseOptions& options);

}  // namespace carom
