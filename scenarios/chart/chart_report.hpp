#pragma once
/// The files `carom chart` writes from its tables, all in OUT (beside the sweep's own
/// summary.csv, summary_by_group.csv, summary.h5 and cases/):
///   chart.csv        one row per variant: cost and, per observable, mean, standard error,
///                    error, uncertainty and the flags (within noise, within tolerance, on the
///                    Pareto front, dominated only within noise)
///   chart_cases.csv  one row per case: variant, seed, status, CPU seconds, simulated seconds,
///                    cost and each observable
///   chart.h5         both tables (layout in CHARTS.md), read by scenarios/plots/chart_plot.py
///   report.md        the cheapest variant within each observable's tolerance, the front
/// Each file is written to a temporary name and renamed, so a reader never sees half a file.
#include <string>

#include "scenarios/chart/chart_spec.hpp"
#include "scenarios/chart/chart_table.hpp"

namespace carom {

/// Writes the four files. Throws std::runtime_error when one cannot be written.
void write_chart(const ChartSpec& chart, const ChartTable& table);

/// The short report (report.md's text).
std::string chart_report(const ChartSpec& chart, const ChartTable& table);

/// A number with `digits` significant digits ("" for NaN), for tables meant to be read.
std::string rounded(double x, int digits = 3);

}  // namespace carom
