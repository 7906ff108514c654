#pragma once
/// One case's directory OUT/cases/NNNN: what it is (case.json), how its last attempt ended
/// (result.json), its log (log.txt) and the outputs of `carom run` (run.h5, checkpoint.h5,
/// summary.json).
///
/// case.json records the case's overrides, seed and a digest of its scene as run (the TOML
/// table after the overrides, so comments do not count). A sweep that finds a case.json that
/// disagrees with the sweep file refuses to run, naming the case: results of two different
/// sweeps are never mixed in one summary.
#include <cstdint>
#include <string>

#include "scenarios/sweep/sweep_spec.hpp"

namespace carom {

/// What the sweep does with a case when it starts.
enum class CaseAction {
  Skip,    ///< Completed (or failed, without --retry-failed): nothing to do.
  Run,     ///< Never run, or retried: `carom run ... --overwrite`.
  Resume,  ///< Interrupted with a checkpoint: `carom resume`.
};

/// How a case's last attempt ended, as result.json records it.
struct CaseResult {
  std::string status =
      "not_run";       ///< completed | interrupted | failed | bad_scene | killed | not_run, or
                       ///< the run's own failure status (inelastic_collapse, kick_unstable).
  int exit_code = -1;  ///< Of the last attempt; -1: none.
  double elapsed_seconds = 0;  ///< Wall time of all attempts together, s.
  double cpu_seconds = 0;      ///< CPU time (user + system) of all attempts together, s.
  int attempts = 0;            ///< How many times a sweep started this case (run or resume).
  int rank = 0;                ///< The MPI rank that ran the last attempt.
  std::string message;         ///< Why it failed: the last line of its log; empty when completed.
  std::string log_tail;        ///< The last lines of its log, when it failed.
};

/// "OUT/cases/0007".
std::string case_directory(const std::string& out, std::size_t index);

/// Digest (FNV-1a, hex) of a scene's text as run, without its first line (which names the file).
std::string scene_digest(const std::string& scene_text);

/// Throws SceneError when dir/case.json exists and records other overrides, seed or scene.
void check_case_record(const std::string& dir, const SweepCase& c, const std::string& digest,
                       const std::string& out);
/// Writes dir/case.json (creating dir) unless it exists.
void write_case_record(const std::string& dir, const SweepCase& c, const std::string& digest,
                       const std::string& scene);

/// The state of a case: result.json if any, corrected by summary.json (a completed run counts
/// as completed even if the sweep that ran it was killed before it recorded so).
CaseResult read_case_result(const std::string& dir);
/// Writes dir/result.json.
void write_case_result(const std::string& dir, const CaseResult& result);
/// What to do with a case in `dir` now.
CaseAction next_action(const std::string& dir, bool retry_failed);

/// The result of an attempt that just ended with `exit_code` (`signal` when killed), read
/// together with the summary.json and log.txt it left. `previous`: the record before it;
/// `wall_seconds` and `cpu_seconds` (s): what the attempt took, added to the case's totals.
CaseResult attempt_result(const std::string& dir, const CaseResult& previous, int exit_code,
                          int signal, bool asked_to_stop, double wall_seconds, int rank,
                          double cpu_seconds);

/// The last `lines` lines of a text file ("" when it cannot be read).
std::string tail_of_file(const std::string& path, std::size_t lines);

}  // namespace carom
