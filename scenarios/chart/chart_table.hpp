#pragma once
/// The results of a chart as tables: one row per case (its cost and observables) and one row
/// per variant (cost and each observable over the seeds, the error against the reference, the
/// tolerance and the Pareto front), from what the sweep gathered in OUT/cases.
///
/// Cost of a case: CPU seconds of its `carom run` / `carom resume` processes (user + system,
/// every attempt, so setup and output writing included; sweep_case.hpp) per simulated second
/// (summary.json's end_time: every case starts at t = 0). Only completed cases enter the
/// statistics.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/chart/chart_spec.hpp"
#include "scenarios/chart/chart_stats.hpp"
#include "scenarios/sweep/sweep_table.hpp"

namespace carom {

/// One run: a variant at one seed.
struct ChartCaseRow {
  std::size_t index = 0;    ///< Case number (directory cases/NNNN).
  std::size_t variant = 0;  ///< Index into ChartSpec::variants.
  std::uint64_t seed = 0;
  std::string status;               ///< As the sweep records it ("completed", ...).
  double cpu_seconds = 0;           ///< s, all attempts.
  double simulated_seconds = 0;     ///< s (NaN: no summary).
  double cost = 0;                  ///< CPU s per simulated s (NaN unless completed).
  std::vector<double> observables;  ///< Per ChartSpec::observables (NaN: missing).
};

/// One observable of one variant.
struct ChartObservableResult {
  SeedStatistics statistics;      ///< Over the completed seeds.
  ErrorEstimate error;            ///< Against the reference.
  bool within_tolerance = false;  ///< |E| <= tolerance.
  FrontMembership front;          ///< In error against cost.
};

/// One variant over its seeds.
struct ChartVariantRow {
  std::size_t cases = 0;                           ///< Seeds run.
  std::size_t completed = 0;                       ///< Of them completed.
  SeedStatistics cost;                             ///< CPU s per simulated s.
  std::vector<ChartObservableResult> observables;  ///< Per ChartSpec::observables.
};

/// Everything a chart measured: its cases, its variants, and per observable the conclusion.
struct ChartTable {
  std::vector<ChartCaseRow> cases;        ///< In case order.
  std::vector<ChartVariantRow> variants;  ///< In variant order.
  /// Per observable: the cheapest variant within its tolerance other than the reference.
  std::vector<std::optional<std::size_t>> cheapest;
  /// Per observable: "" or why it could not be compared (no completed case has it), with the
  /// chart file's line and the closest numbers summary.json holds.
  std::vector<std::string> problems;
};

/// The chart's tables from the sweep's table of its cases (gather_sweep).
ChartTable chart_table(const ChartSpec& chart, const SweepTable& sweep);

}  // namespace carom
