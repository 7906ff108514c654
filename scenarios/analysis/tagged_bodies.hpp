#pragma once
/// Tagged bodies' time series (scene: `tagged = true` on [[particles]] entries; SCENES.md), from
/// the impulses each method books at its collisions (events/tagged_impulses.hpp). With T bodies
/// and C = S + W partner categories (species, then walls), every sample adds to /timeseries:
///   tagged_position          T x 3, m
///   tagged_velocity          T x 3, m/s
///   tagged_impulse           T x C x 3, collision impulse since t = 0 by partner, N s
///   tagged_force             T x 3, mean collision force over the window since the previous
///                            sample (impulse booked in it / its length), N; NaN at the first
///   tagged_force_by_partner  T x C x 3, the same per partner category, N
///   tagged_mean_velocity     3, mean over the bodies, m/s
///   tagged_mean_force        3, mean over the bodies of tagged_force, N
/// The conclusions fit the group's deceleration: 1/V = 1/V0 + k t (drag_fit.hpp), V the mean
/// velocity's component along its direction at the first sample.
#include <string>
#include <utility>
#include <vector>

#include "events/method.hpp"
#include "scenarios/analysis/drag_fit.hpp"

namespace carom {

struct SeriesColumn;

/// The tagged-body series and their widths for T bodies and C partner categories (none for T = 0).
std::vector<std::pair<std::string, std::size_t>> tagged_series_widths(std::size_t bodies,
                                                                      std::size_t partners);

/// Appends the tagged-body series at sim.time() to `row`. `previous_impulse`: the
/// tagged_impulse row of the previous sample (nullptr: none, the window forces are NaN) taken at
/// `previous_time`, s.
void sample_tagged_bodies(const CollisionMethod& sim, const double* previous_impulse,
                          double previous_time, std::vector<SeriesColumn>& row);

/// What the run concludes about its tagged bodies.
struct TaggedConclusions {
  std::size_t bodies = 0;
  std::vector<std::uint64_t> ids;
  Vec3 direction = Vec3::Zero();  ///< Unit vector of the mean velocity at the first sample.
  double start_speed = 0;         ///< Mean velocity along `direction` at the first sample, m/s.
  double end_speed = 0;           ///< The same at the last sample, m/s.
  /// Mean collision force on one body over the whole record (impulse / duration), N, and its
  /// component along `direction` (negative: drag).
  Vec3 mean_force = Vec3::Zero();
  InverseSpeedFit fit;  ///< 1/V = intercept + k t over the record.
};

/// Concludes from the record: times (s) and the tagged_mean_velocity and tagged_impulse series.
TaggedConclusions conclude_tagged(const std::vector<std::uint64_t>& ids, std::size_t partners,
                                  const std::vector<double>& times,
                                  const std::vector<double>& mean_velocity,
                                  const std::vector<double>& impulse);

/// The "tagged_bodies" object of summary.json (JSON text).
std::string tagged_json(const TaggedConclusions& c);
/// The tagged-body section of report.md ("" without tagged bodies).
std::string tagged_report(const TaggedConclusions& c);

}  // namespace carom
