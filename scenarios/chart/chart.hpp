#pragma once
/// `carom chart CHART.toml`: speed against accuracy. One scene run as several variants over
/// the same seeds through the sweep runner (so --jobs, mpirun, resume of an interrupted chart
/// and the OUT/cases layout are the sweep's, SWEEPS.md); then, per variant, the cost (CPU
/// seconds per simulated second) and each observable's mean, standard error and error against
/// the reference variant; the Pareto front of error against cost; and the cheapest variant
/// within each observable's tolerance (CHARTS.md).
///
/// Exit codes: those of the sweep (0 every case completed; 1 some case did not; 2 bad chart
/// file, bad case or usage; 130 interrupted), and 2 when an observable is in no completed
/// case's summary.json (the tables are still written, the message names the chart file's line).
#include <cstddef>
#include <optional>
#include <string>

namespace carom {

struct ChartOptions {
  std::string file;                ///< The chart file.
  std::optional<std::string> out;  ///< Replaces the file's `out`.
  std::size_t jobs = 1;            ///< Cases at once on each rank.
  bool quiet = false;              ///< No progress lines (errors are still printed).
  bool retry_failed = false;       ///< Run failed cases again (from their start).
  bool dry_run = false;            ///< Validate every case and list them; run nothing.
};

/// Runs a chart; returns its exit code. Prints its own errors (on rank 0 under mpirun).
int run_chart(const ChartOptions& options);

}  // namespace carom
