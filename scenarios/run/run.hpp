#pragma once
/// The run loop behind `carom run` and `carom resume`: run_until in chunks, outputs on their
/// schedule, a clean stop with a checkpoint on SIGINT/SIGTERM, summary.json at the end.
///
/// Exit codes (reliable; the tests check them):
///   0    the run reached its end time
///   1    runtime failure: inelastic collapse, an output that cannot be written, a bad checkpoint
///   2    bad scene or bad usage: nothing was run and nothing was written
///   130  interrupted by SIGINT or SIGTERM: a checkpoint was written, `carom resume DIR` continues.
///        A signal before t = 0 (while the particles are placed or settled) writes nothing: the
///        run had not started (InterruptedBeforeStart, with a message that says so).
///        The signal is acted on between chunks of run_until (about 0.2 s of wall time); a second
///        signal exits at once with 130 and no new checkpoint (the last periodic one remains).
///
/// An output directory holds run.h5 (+ run.xmf), checkpoint.h5 and summary.json. Outputs are
/// written at k * interval (k = 0, 1, ...) of simulated time and at the end, so a resumed run
/// writes exactly what the uninterrupted one would have (plus the extra end-of-stretch rows).
#include <csignal>
#include <memory>
#include <optional>
#include <string>

#include "events/method.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

class FlowBoundaries;  // events/flow/flow_boundaries.hpp
class GasCoupling;     // fluid/coupling.hpp
struct Checkpoint;     // scenarios/run/run_output.hpp

enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitUsage = 2, kExitInterrupted = 130 };

struct RunOptions {
  std::string out_dir;     ///< Output directory (created; must not already hold a run unless overwrite).
  bool quiet = false;      ///< No progress line and no chatter on stdout.
  bool overwrite = false;  ///< Replace the outputs of an earlier run in out_dir.
};

/// A scene's collision method at t = 0 with its inflows, outflows and gas attached: what
/// `carom run` steps, and what the Python module's Simulation steps. The method's actions call
/// into the flow and the gas, so the three are kept, and destroyed, together.
struct StartedRun {
  std::unique_ptr<CollisionMethod> method;
  std::unique_ptr<FlowBoundaries> flow;  ///< Null without inflows and outflows.
  std::unique_ptr<GasCoupling> gas;      ///< Null without a coupled gas.
  StartedRun();
  StartedRun(StartedRun&&) noexcept;
  StartedRun& operator=(StartedRun&&) noexcept;
  ~StartedRun();
};

/// Makes the method of a scene whose initial state is built (build_initial_state), tags its
/// bodies, and attaches the flow and the gas, as `carom run` does before its first step.
/// Throws SceneError for what the scene's method, flow or gas cannot run.
StartedRun start_run(const Scene& scene);

/// The same from a checkpoint whose state has been checked (check_checkpoint_state), with the
/// scene stored in it, as `carom resume` continues it: bit for bit. `path` names the
/// checkpoint in messages. Throws SceneError for a state the scene cannot continue.
StartedRun restore_run(const Scene& scene, const Checkpoint& checkpoint, const std::string& path);

/// Validates (particles placed, initial state checked) before anything is created, then runs.
/// Throws SceneError for a bad scene or an unusable output directory (exit 2).
int run_scene(Scene scene, const RunOptions& options);

/// Continues the run in `dir` from its checkpoint to `end_time` (default: the scene's end).
/// Throws SceneError when dir holds no checkpoint or end_time is before the checkpoint (exit 2).
int resume_run(const std::string& dir, std::optional<double> end_time, bool quiet);

/// Installs the SIGINT/SIGTERM handlers that ask the run loop to stop at the next chunk.
void install_stop_handlers();
/// The flag those handlers raise (for a settling run before t = 0, build_initial_state).
const volatile std::sig_atomic_t* stop_flag();
/// Lowers that flag: for a process that goes on after a run it stopped (the Python module),
/// so that its next run does not stop at once. The command line never needs it.
void clear_stop_request();

}  // namespace carom
