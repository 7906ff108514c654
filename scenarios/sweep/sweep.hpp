#pragma once
/// `carom sweep SWEEP.toml`: one scene over a grid of scene-key values and seeds (SWEEPS.md).
///
/// Steps: read the sweep file; parse every case's scene (all mistakes reported together, exit
/// 2, nothing written); compare with what OUT/cases already holds (a case recorded with other
/// overrides is an error); decide per case: skip (completed, or failed without
/// --retry-failed), resume (interrupted with a checkpoint) or run; place the particles of every
/// case to be run (`carom check`, exit 2 if any fails, nothing run); run the cases as child
/// processes, `jobs` at a time per rank; write the summary (summary.hpp of each case gathered
/// into OUT/summary.csv, summary_by_group.csv, summary.h5).
///
/// Under mpirun, the cases still to do are dealt out round-robin over the ranks (the k-th case
/// to do goes to rank k % size); rank 0 writes the summary after all ranks are done. OUT must be
/// on a file system every rank sees.
///
/// Exit codes: 0 every case completed; 1 some case did not complete (failed now or before; the
/// summary is still written); 2 bad sweep file, bad case or bad usage (nothing run); 130
/// interrupted by SIGINT/SIGTERM (running cases checkpointed, summary of what is done written).
#include <cstddef>
#include <optional>
#include <string>

#include "scenarios/sweep/sweep_spec.hpp"

namespace carom {

struct SweepOptions {
  std::string file;                ///< The sweep file.
  std::optional<std::string> out;  ///< Replaces the file's `out`.
  std::size_t jobs = 1;            ///< Cases at once on each rank.
  bool quiet = false;              ///< No progress lines (errors are still printed).
  bool retry_failed = false;       ///< Run failed cases again (from their start).
  bool dry_run = false;            ///< Validate every case and list them; run nothing.
  /// Hooks for commands built on the sweep (`carom chart`): a spec already read from `file`
  /// (then `file` is not read as a sweep file, only copied into OUT), the name that starts
  /// every message, and the name of the copy of `file` in OUT.
  std::optional<SweepSpec> spec;
  std::string command = "carom sweep";
  std::string record_name = "sweep.toml";
};

/// Runs a sweep; returns its exit code. Prints its own errors (on rank 0 under mpirun).
int run_sweep(const SweepOptions& options);

}  // namespace carom
