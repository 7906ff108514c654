#pragma once
/// The files a sweep writes from its tables, all in OUT:
///   summary.csv           one row per case: case, group, each varied key, seed, status,
///                         exit_code, elapsed_seconds, attempts, every metric, message
///   summary_by_group.csv  one row per group: group, each varied key, n_cases, n_completed,
///                         then METRIC:mean and METRIC:std for every metric
///   summary.h5            the same tables, one dataset per column (layout in SWEEPS.md)
/// Missing numbers are empty cells in the CSV files and NaN in the HDF5 file. Each file is
/// written to a temporary name and renamed, so a reader never sees half a file.
#include <string>

#include "scenarios/sweep/sweep_spec.hpp"
#include "scenarios/sweep/sweep_table.hpp"

namespace carom {

/// Writes the three summary files. Throws std::runtime_error when one cannot be written.
void write_sweep_summary(const SweepSpec& spec, const SweepTable& table);

/// One CSV cell: the text, quoted when it holds a comma, a quote or a line break.
std::string csv_cell(const std::string& text);

/// A key as an HDF5 dataset name: '/' (a group separator there) becomes '_'.
std::string dataset_name(std::string key);

}  // namespace carom
