#pragma once
/// The results of a sweep as tables: one row per case (how it ended and every numeric leaf of
/// its summary.json), and one row per group of cases that share their varied values (mean and
/// sample standard deviation over the completed seeds).
///
/// Metrics are found generically: every number in summary.json, nested objects and arrays
/// flattened with dots ("collision_rate_per_particle.a-b", "wall_force.z_low.2"), in the
/// order of the first case that has them. Nothing here knows what a metric means.
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "scenarios/sweep/sweep_case.hpp"
#include "scenarios/sweep/sweep_spec.hpp"

namespace carom {

/// A number that is absent (printed as an empty cell, stored as NaN).
inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

/// One case: its identity, its result and its metrics (kMissing where it has none).
struct CaseRow {
  SweepCase c;                  ///< Index, group, seed, choices.
  CaseResult result;            ///< Status, exit code, elapsed wall time, message.
  std::vector<double> metrics;  ///< One per SweepTable::metrics.
};

/// One combination of varied values.
struct GroupRow {
  std::size_t group = 0;
  std::size_t cases = 0;       ///< Cases (seeds) in the group.
  std::size_t completed = 0;   ///< Of them completed: the ones the statistics use.
  std::vector<double> mean;    ///< Per metric, over the completed cases that have it.
  std::vector<double> stddev;  ///< Sample standard deviation (n - 1); kMissing when n < 2.
};

struct SweepTable {
  std::vector<std::string> metrics;  ///< Flattened names, in first-seen order.
  std::vector<CaseRow> cases;        ///< In case order.
  std::vector<GroupRow> groups;      ///< In group order.
};

/// Every numeric leaf of a JSON text, flattened with dots (booleans and strings are skipped).
std::vector<std::pair<std::string, double>> numeric_leaves(const std::string& json_text);

/// Reads every case's result.json and summary.json under spec.out and computes the groups.
SweepTable gather_sweep(const SweepSpec& spec, const std::vector<SweepCase>& cases);

/// Names of the columns of a case row besides its metrics (a metric of the same name is renamed
/// "summary.NAME").
std::vector<std::string> fixed_case_columns(const SweepSpec& spec);

}  // namespace carom
