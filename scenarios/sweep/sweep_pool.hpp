#pragma once
/// A pool of child processes of this same binary (`carom run ...`, `carom resume ...`), at
/// most `slots` at a time, and the sweep's handling of SIGINT/SIGTERM.
///
/// Children are started with posix_spawn (no fork: safe inside an MPI rank) in their own
/// process group, stdin from /dev/null, stdout and stderr appended to a log file. A Ctrl-C at
/// the terminal therefore reaches only the sweep, which forwards each signal it receives once
/// to every running child: the first makes a child write a checkpoint and exit 130, a second
/// makes it exit at once (as for `carom run`).
#include <sys/types.h>

#include <chrono>
#include <csignal>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace carom {

/// Environment variable through which a sweep's case learns the sweep's process id
/// (follow_sweep_parent).
inline constexpr const char* kSweepParentVariable = "CAROM_SWEEP_PARENT";

/// In a case started by a sweep (kSweepParentVariable set): asks the kernel for SIGTERM when the
/// sweep process ends (the case then checkpoints and exits 130, as on a Ctrl-C), and returns
/// false when the sweep is already gone (the case must not start). True otherwise.
bool follow_sweep_parent();

/// How a child ended.
struct ChildExit {
  std::size_t tag = 0;         ///< What the caller started it for (a case index).
  int exit_code = 0;           ///< Its exit status; 128 + signal when a signal killed it.
  int signal = 0;              ///< The signal that killed it, 0 when it exited.
  bool asked_to_stop = false;  ///< A stop signal was forwarded to it.
  double wall_seconds = 0;     ///< s from start to exit.
  double cpu_seconds = 0;      ///< CPU time it used, user + system (wait4's rusage), s.
};

class ProcessPool {
 public:
  /// `slots`: the most children at once (>= 1).
  explicit ProcessPool(std::size_t slots);
  /// Signals every child still running with SIGTERM and waits for it.
  ~ProcessPool();
  ProcessPool(const ProcessPool&) = delete;
  ProcessPool& operator=(const ProcessPool&) = delete;

  /// True when another child may start now.
  bool has_free_slot() const { return running_.size() < slots_; }
  /// True when no child is running.
  bool idle() const { return running_.empty(); }
  /// Starts this binary with `args` (argv[1...]), output appended to `log_path`. Throws
  /// std::runtime_error when the process cannot be started.
  void start(std::size_t tag, const std::vector<std::string>& args, const std::string& log_path);
  /// Waits until a child ends and returns it; returns nullopt at once when none is running.
  /// Forwards stop signals to the children while it waits.
  std::optional<ChildExit> wait();

 private:
  struct Child {
    std::size_t tag;
    pid_t pid;
    std::chrono::steady_clock::time_point start;
    int signals_forwarded;
  };
  /// Sends every stop signal received since the last call to the running children.
  void forward_signals();

  std::size_t slots_;
  std::vector<Child> running_;
  std::string executable_;
};

/// Makes the cases of every later pool run `path` instead of this binary: for a process that is
/// not carom itself (the Python module names the carom binary it was built with).
void set_case_executable(std::string path);

/// Installs the sweep's SIGINT/SIGTERM handlers (they only record the signal), with no stop
/// recorded yet.
void install_sweep_signal_handlers();
/// True once SIGINT or SIGTERM reached the sweep: start nothing new.
bool sweep_stop_requested();
/// The flag those handlers raise (non-zero after a stop signal), for a placement that checks it.
const volatile std::sig_atomic_t* sweep_stop_flag();

}  // namespace carom
