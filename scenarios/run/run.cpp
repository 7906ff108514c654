#include "scenarios/run/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

#include <sys/time.h>
#include <unistd.h>

#include "scenarios/run/checkpoint_check.hpp"
#include "scenarios/run/flow_run.hpp"
#include "scenarios/run/output_lock.hpp"
#include "scenarios/run/gas_run.hpp"
#include "scenarios/run/output_estimate.hpp"
#include "scenarios/run/progress.hpp"
#include "scenarios/analysis/run_analysis.hpp"
#include "scenarios/run/run_output.hpp"
#include "scenarios/run/summary.hpp"
#include "scenarios/scene/settling.hpp"

namespace carom {

namespace fs = std::filesystem;

namespace {

volatile std::sig_atomic_t g_stop = 0;

/// First signal: ask the run to stop (run_until checks the flag every few thousand events), write a
/// checkpoint and exit. Second signal (the user insists): leave at once, without a checkpoint.
extern "C" void on_stop_signal(int) {
  if (g_stop == 1) {
    static const char message[] = "\ncarom: second interrupt: stopping without a checkpoint\n";
    const ssize_t ignored = write(STDERR_FILENO, message, sizeof(message) - 1);
    (void)ignored;
    _exit(kExitInterrupted);
  }
  g_stop = 1;
}

/// The stall watch's timer (SIGALRM): makes run_until return (g_stop = 2) so that the run loop
/// can look at the simulated time even inside one long chunk; the loop clears it and goes on.
/// Returning there changes no bit of the run (as for a chunk's end). A stop asked by a signal
/// (g_stop = 1) is never overwritten.
extern "C" void on_watch_alarm(int) {
  if (g_stop == 0) g_stop = 2;
}

/// Arms the watch timer every `seconds` of wall time for its lifetime.
class WatchTimer {
 public:
  explicit WatchTimer(double seconds) {
    struct sigaction action {};
    action.sa_handler = on_watch_alarm;
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    action.sa_flags = SA_RESTART;
    sigaction(SIGALRM, &action, nullptr);
    itimerval every{};
    every.it_interval.tv_sec = static_cast<time_t>(seconds);
    every.it_interval.tv_usec = static_cast<suseconds_t>((seconds - std::floor(seconds)) * 1e6);
    every.it_value = every.it_interval;
    setitimer(ITIMER_REAL, &every, nullptr);
  }
  ~WatchTimer() {
    itimerval off{};
    setitimer(ITIMER_REAL, &off, nullptr);
    signal(SIGALRM, SIG_IGN);
  }
  /// Clears a watch stop (g_stop = 2), never a signal's, with the signals held meanwhile.
  static void clear() {
    sigset_t held, previous;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    sigaddset(&held, SIGALRM);
    sigprocmask(SIG_BLOCK, &held, &previous);
    if (g_stop == 2) g_stop = 0;
    sigprocmask(SIG_SETMASK, &previous, nullptr);
  }
  WatchTimer(const WatchTimer&) = delete;
  WatchTimer& operator=(const WatchTimer&) = delete;
};

/// A random run id (never 0, which marks files from before run ids). Drawn from the system's
/// entropy, not the scene's seed: it identifies the run and touches no physics.
std::uint64_t new_run_id() {
  std::random_device entropy;
  std::uint64_t id = 0;
  while (id == 0) id = (std::uint64_t(entropy()) << 32) ^ entropy();
  return id;
}

std::string hex(std::uint64_t value) {
  std::ostringstream out;
  out << std::hex << std::setw(16) << std::setfill('0') << value;
  return out.str();
}

/// The "run" object of summary.json: the identity run.h5 and checkpoint.h5 carry too.
std::string run_identity_json(const RunInfo& info) {
  return "{\"id\": \"" + hex(info.run_id) + "\", \"scene_hash\": \"" + hex(info.scene_hash()) +
         "\", \"seed\": " + std::to_string(info.seed) + ", \"method\": " + json_string(info.method) + "}";
}

/// Output instants k * interval, k = 0, 1, ... (computed, never accumulated, so a resumed run
/// meets exactly the same instants). interval 0: none.
struct Schedule {
  double interval = 0;
  std::uint64_t k = 0;

  double next() const { return interval > 0 ? static_cast<double>(k) * interval : kNever; }
  /// True when the next instant is t (up to round-off in k * interval).
  bool due(double t) const { return interval > 0 && next() <= t + 1e-12 * std::max(std::abs(t), interval); }
  /// Moves past every instant up to and including t.
  void pass(double t) {
    if (interval <= 0) return;
    while (due(t)) ++k;
  }
  /// Positions the schedule at the first instant after t (after a resume).
  void start_after(double t) {
    if (interval <= 0) return;
    k = static_cast<std::uint64_t>(std::max(0.0, std::floor(t / interval)));
    while (k > 0) {  // round-off in t / interval may overshoot by one
      --k;
      if (due(t)) break;
    }
    pass(t);
  }
};

/// A run whose simulated time has stopped advancing: the detector below ends it (exit 1).
class RunStalled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Watches the simulated time against the wall time: when over kWindow seconds of wall time
/// the run advanced by less than kFraction of its whole length, it would need more than
/// kWindow / kFraction (190 years) to end, so it is stopped with the cause named: the fastest
/// particle's speed and the events per simulated second. A run that merely slows down (a dense
/// phase, a small time step) stays far above this rate.
class StallWatch {
 public:
  static constexpr double kWindow = 60.0;    ///< Wall-clock seconds between checks.
  static constexpr double kFraction = 1e-8;  ///< Least advance per window, of end - start.

  StallWatch(const CollisionMethod& sim, double end_time)
      : length_(end_time - sim.time()), time_(sim.time()), events_(sim.statistics().events) {
    // For tests only: a shorter window (CAROM_STALL_WINDOW_SECONDS).
    if (const char* text = std::getenv("CAROM_STALL_WINDOW_SECONDS")) window_ = std::max(0.1, std::atof(text));
  }
  /// Wall-clock seconds between looks.
  double window() const { return window_; }
  void check(const CollisionMethod& sim, double wall) {
    if (wall - wall_ < window_) return;
    const double advanced = sim.time() - time_;
    const std::uint64_t events = sim.statistics().events - events_;
    if (advanced < kFraction * length_) {
      double fastest = 0;
      for (std::size_t i = 0; i < sim.particle_count(); ++i) fastest = std::max(fastest, sim.velocity(i).norm());
      throw RunStalled("the run has stalled at t = " + format_number(sim.time()) + " s: its simulated time advanced " +
                       format_number(advanced) + " s in the last " + format_number(wall - wall_) +
                       " s of wall time (" + std::to_string(events) + " events), less than " + format_number(kFraction) +
                       " of the run's length " + format_number(length_) + " s per " + format_number(window_) +
                       " s; it would not reach its end. The fastest particle moves at " + format_number(fastest) +
                       " m/s: an absurd speed or temperature, or a time step or collision rate far too fine for the "
                       "run's length");
    }
    wall_ = wall;
    time_ = sim.time();
    events_ = sim.statistics().events;
  }

 private:
  double window_ = kWindow;
  double length_;
  double time_;
  std::uint64_t events_;
  double wall_ = 0;
};

/// The loop shared by run and resume. `fresh`: a new run, whose t = 0 outputs are written here.
int run_loop(CollisionMethod& sim, const GasCoupling* gas, const FlowBoundaries* flow, RunFile& file,
             RunAnalysis& analysis, const Scene& scene, const RunInfo& info, const fs::path& dir,
             double end_time, bool fresh, bool quiet) {
  install_stop_handlers();
  const std::string checkpoint_path = (dir / "checkpoint.h5").string();
  const std::string summary_path = (dir / "summary.json").string();
  const std::string report_path = (dir / "report.md").string();
  RunStretch stretch;
  stretch.start_time = sim.time();
  stretch.start_statistics = sim.statistics();
  stretch.run_json = run_identity_json(info);
  stretch.gas = gas;
  if (gas != nullptr) stretch.gas_start = gas->times();
  stretch.flow = flow;
  analysis.set_flow(flow);
  if (flow != nullptr) stretch.flow_start = flow_start(*flow, sim.time());
  stretch.averages.sample(sim);
  auto append_sample = [&] {
    SeriesRow row = analysis.sample(sim, gas);
    if (flow != nullptr) append_flow_series(*flow, sim, row);
    file.append_sample(sim, gas, row);
  };
  // The rows up to a checkpoint are in the run file before it (a resumed run reads them back).
  auto checkpoint = [&] {
    file.write_waiting_rows();
    write_checkpoint(checkpoint_path, sim, info, gas, flow);
  };

  Schedule snapshots{scene.output.snapshot_every}, samples{scene.output.sample_every},
      checkpoints{scene.output.checkpoint_every};
  // The time averages of summary.json are taken on a schedule of simulated time (the samples',
  // or 200 instants over the run), never at wall-clock chunk ends, so they are reproducible.
  Schedule averages{scene.output.sample_every > 0 ? scene.output.sample_every : scene.end_time / 200.0};
  averages.start_after(sim.time());
  double last_snapshot = sim.time(), last_sample = sim.time();
  if (fresh) {
    file.write_snapshot(sim, gas);
    append_sample();
    snapshots.pass(sim.time());
    samples.pass(sim.time());
    checkpoints.pass(sim.time());
  } else {
    snapshots.start_after(sim.time());
    samples.start_after(sim.time());
    checkpoints.start_after(sim.time());
  }

  const auto wall_start = std::chrono::steady_clock::now();
  auto wall_seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };
  ProgressLine progress(!quiet, sim.time(), end_time);
  // Chunks of simulated time sized for about 0.2 s of wall time each: short enough for a prompt
  // reaction to a signal, long enough that the loop costs nothing. They do not change the
  // dynamics: run_until's end is a global event that touches no particle.
  double chunk = (end_time - sim.time()) / 1000.0;
  auto finish = [&](const std::string& status, const std::string& message) {
    file.write_waiting_rows();
    progress.finish();
    stretch.status = status;
    stretch.message = message;
    stretch.wall_seconds = wall_seconds();
    analysis.write_results(file.path(), sim);
    stretch.analysis_json = analysis.summary_json(sim);
    write_text_atomically(summary_path, summary_json(sim, scene, stretch));
    write_text_atomically(report_path, analysis.report(sim));
  };

  // A signal also stops run_until itself within a few thousand events, so even a chunk that
  // takes long (a dense, slow phase) is interrupted promptly, at a consistent state.
  sim.set_stop_flag(&g_stop);
  // A failure ends the run with summary.json written where there is room, and says so where not.
  auto end_with = [&](const std::string& status, const std::string& message) {
    try {
      finish(status, message);
    } catch (const std::exception& e) {
      std::cerr << "carom: " << message << "\n";
      std::cerr << "carom: summary.json could not be written either: " << e.what() << "\n";
      return kExitFailure;
    }
    std::cerr << "carom: " << message << "\n";
    return kExitFailure;
  };
  StallWatch stall(sim, end_time);
  const WatchTimer watch_timer(std::min(stall.window(), 10.0));
  try {
    while (sim.time() < end_time) {
      const double chunk_end = sim.stop_time(sim.time() + chunk);
      const double target = std::min({end_time, chunk_end, snapshots.next(), samples.next(),
                                      checkpoints.next(), averages.next()});
      const bool chunk_limited = target == chunk_end;
      const auto chunk_start = std::chrono::steady_clock::now();
      sim.run_until(target);
      const double t = sim.time();
      if (snapshots.due(t)) {
        file.write_snapshot(sim, gas);
        last_snapshot = t;
        snapshots.pass(t);
      }
      if (samples.due(t)) {
        append_sample();
        last_sample = t;
        samples.pass(t);
      }
      if (checkpoints.due(t)) {
        checkpoint();
        checkpoints.pass(t);
      }
      if (averages.due(t) || t >= end_time) {
        stretch.averages.sample(sim);
        averages.pass(t);
      }
      file.write_overdue_rows();
      progress.update(t, sim.statistics().events, sim.statistics().collisions());
      const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - chunk_start).count();
      if (chunk_limited)
        chunk *= std::clamp(0.2 / std::max(spent, 1e-6), 0.5, 2.0);
      WatchTimer::clear();
      stall.check(sim, wall_seconds());
      if (g_stop == 1) {
        checkpoint();
        finish("interrupted", "stopped by a signal at t = " + format_number(t) + " s; continue with: carom resume " + dir.string());
        std::cerr << "carom: interrupted at t = " << t << " s; checkpoint written. Continue with: carom resume "
                  << dir.string() << "\n";
        return kExitInterrupted;
      }
    }
    if (last_snapshot < sim.time()) file.write_snapshot(sim, gas);
    if (last_sample < sim.time()) append_sample();
    checkpoint();
    finish("completed", "");
  } catch (const InelasticCollapse& e) {
    return end_with("inelastic_collapse", e.what());
  } catch (const KickUnstable& e) {
    return end_with("kick_unstable", e.what());
  } catch (const MethodFailure& e) {
    return end_with(e.status, e.what());
  } catch (const RunStalled& e) {
    return end_with("stalled", e.what());
  } catch (const std::exception& e) {  // an output that cannot be written: a full disk, an HDF5 error
    return end_with("failed", std::string("failed: ") + e.what());
  }
  if (flow != nullptr)  // an inlet slab that was full: the set mass flow was not met
    for (std::size_t k = 0; k < flow->inflows().size(); ++k)
      if (const std::string message = flow->blocked_message(k); !message.empty())
        std::cerr << "carom: warning: " << message << "\n";
  if (!quiet) {
    const RunStatistics& s = sim.statistics();
    std::cout << "carom: " << scene.name << " reached t = " << sim.time() << " s: " << s.events << " events, "
              << s.collisions() << " collisions, " << stretch.wall_seconds << " s wall time. Outputs in "
              << dir.string() << "\n";
  }
  return kExitOk;
}

/// Creates the output directory and takes its lock (output_lock.hpp), then refuses to mix a new
/// run with an earlier one's files. Those are carom's own file names only: its outputs, and the
/// figures scenarios/plots/plot.py draws beside run.h5 (RUN_NAME.png; a test checks this list
/// against plot.py) and the default image of scenarios/plots/paraview_snapshot.py
/// (run_snapshot_3d.png). --overwrite removes them, only once the lock is held, so never what
/// another process is writing; anything else in the directory is left alone.
std::unique_ptr<OutputLock> prepare_output_directory(const fs::path& dir, bool overwrite) {
  const char* outputs[] = {"run.h5",
                           "run.xmf",
                           "run_gas.xmf",
                           "checkpoint.h5",
                           "summary.json",
                           "report.md",
                           "run_energies.png",
                           "run_collision_rates.png",
                           "run_snapshot.png",
                           "run_snapshot_3d.png",
                           "run_gas.png",
                           "run_gas_field.png",
                           "run_mixing.png",
                           "run_collisions.png",
                           "run_profiles.png",
                           "run_flow.png",
                           "run_plugs.png",
                           "run_bed.png",
                           "run_bed_spectrum.png",
                           "run_bed_map.png"};
  std::error_code error;
  if (fs::exists(dir, error) && !fs::is_directory(dir, error))
    throw SceneError(dir.string() + ": --out names a file, not a directory");
  fs::create_directories(dir, error);
  if (error) throw SceneError(dir.string() + ": cannot create the output directory: " + error.message());
  auto lock = std::make_unique<OutputLock>(dir, overwrite ? "carom run --overwrite" : "carom run");
  for (const char* name : outputs) {
    if (!fs::exists(dir / name, error)) continue;
    if (!overwrite)
      throw SceneError(dir.string() + " already holds the outputs of a run (" + name +
                       "); choose another --out, remove them, or pass --overwrite");
    fs::remove(dir / name, error);
  }
  return lock;
}

}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

const volatile std::sig_atomic_t* stop_flag() { return &g_stop; }

void clear_stop_request() { g_stop = 0; }

StartedRun::StartedRun() = default;
StartedRun::StartedRun(StartedRun&&) noexcept = default;
StartedRun& StartedRun::operator=(StartedRun&&) noexcept = default;
StartedRun::~StartedRun() = default;

StartedRun start_run(const Scene& scene) {
  StartedRun started;
  try {
    started.method = make_method(scene.system, scene.method);
    started.method->tag_bodies(scene.analysis.tagged_bodies);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": " + e.what());
  }
  try {
    started.flow = attach_flow(*started.method, scene);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": [[inflow]]/[[outflow]]: " + e.what());
  }
  try {
    started.gas = attach_gas(*started.method, scene);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": [gas]: " + e.what());
  }
  return started;
}

StartedRun restore_run(const Scene& scene, const Checkpoint& checkpoint, const std::string& path) {
  StartedRun restored;
  try {
    restored.method = restore_method(scene.system, scene.method, checkpoint.method_state());
    restored.method->tag_bodies(scene.analysis.tagged_bodies);
  } catch (const std::exception& e) {
    throw SceneError(path + ": cannot continue from this checkpoint: " + e.what());
  }
  try {
    std::optional<h5::Group> saved_flow;
    if (checkpoint.has_flow()) saved_flow = checkpoint.flow_state();
    if (scene.flow.any() && !saved_flow)
      throw std::runtime_error("the scene has inflows or outflows but the checkpoint holds no /flow state");
    restored.flow = attach_flow(*restored.method, scene, saved_flow ? &*saved_flow : nullptr);
  } catch (const std::exception& e) {
    throw SceneError(path + ": cannot continue from this checkpoint: " + e.what());
  }
  try {
    std::optional<h5::Group> saved_gas;
    if (checkpoint.has_gas()) saved_gas = checkpoint.gas_state();
    restored.gas = attach_gas(*restored.method, scene, saved_gas ? &*saved_gas : nullptr);
  } catch (const std::invalid_argument& e) {
    throw SceneError(path + ": cannot continue from this checkpoint: " + e.what());
  }
  return restored;
}

int run_scene(Scene scene, const RunOptions& options) {
  // Everything that can be wrong with a scene is found before the first file is created. A
  // signal meanwhile (placing, settling) stops it with nothing written.
  install_stop_handlers();
  const OutputEstimate estimate = estimate_output(scene, planned_particle_count(scene));
  check_output_size(scene, estimate, options.out_dir);
  if (const std::string warning = output_size_warning(scene, estimate); !warning.empty() && !options.quiet)
    std::cerr << "carom: warning: " << warning << "\n";
  build_initial_state(scene, stop_flag());
  if (g_stop)
    throw InterruptedBeforeStart("interrupted while the particles were placed, before the run's t = 0: nothing "
                                 "was written; run the same command again to start over");
  StartedRun started = start_run(scene);
  CollisionMethod& sim = *started.method;
  const fs::path dir = options.out_dir;
  const std::unique_ptr<OutputLock> lock = prepare_output_directory(dir, options.overwrite);
  const RunInfo info{scene.text, scene.name, scene.seed, std::string(method_name(scene.method.kind)), new_run_id()};
  // A run file that cannot be started (an attribute HDF5 refuses, a full disk) is removed, so
  // that it does not block the corrected rerun.
  std::unique_ptr<RunFile> file;
  std::unique_ptr<RunAnalysis> analysis;
  try {
    file = std::make_unique<RunFile>((dir / "run.h5").string(), info, sim.system(), started.gas.get());
    analysis = std::make_unique<RunAnalysis>(scene, sim);
    analysis->write_setup(file->path());
  } catch (...) {
    file.reset();
    std::error_code ignored;
    fs::remove(dir / "run.h5", ignored);
    fs::remove(dir / "run.xmf", ignored);
    fs::remove(dir / "run_gas.xmf", ignored);
    throw;
  }
  return run_loop(sim, started.gas.get(), started.flow.get(), *file, *analysis, scene, info, dir, scene.end_time,
                  true, options.quiet);
}

int resume_run(const std::string& directory, std::optional<double> end_time, bool quiet) {
  const fs::path dir = directory;
  const fs::path checkpoint_path = dir / "checkpoint.h5";
  if (!fs::is_directory(dir) || !fs::exists(checkpoint_path)) {
    // A run still running may not have written its first checkpoint yet: say so first.
    if (fs::exists(dir / kLockFile)) const OutputLock probe(dir, "carom resume");
    throw SceneError(directory + ": no checkpoint.h5 here; `carom resume` needs the output directory of a run");
  }
  const OutputLock lock(dir, "carom resume");
  Checkpoint checkpoint;
  try {
    checkpoint = read_checkpoint(checkpoint_path.string());
  } catch (const std::exception& e) {
    throw SceneError(std::string(e.what()) + " (cannot resume from it)");
  }
  const std::string scene_file = checkpoint_path.string() + " (stored scene)";
  std::vector<std::string> overrides;
  if (end_time) overrides.push_back("time.end=" + format_number(*end_time));
  Scene scene = parse_scene(checkpoint.info.scene_text, scene_file, overrides);
  const double now = checkpoint.method_state().attribute<double>("time");
  const double end = scene.end_time;
  if (end < now)
    throw SceneError(directory + ": the end time " + format_number(end) + " s is before the checkpoint's time " +
                     format_number(now) + " s");
  // Everything is checked before the method is rebuilt from it: a damaged state is refused.
  check_checkpoint_state(checkpoint, scene.system);
  check_run_file_matches((dir / "run.h5").string(), checkpoint);
  RunInfo info = checkpoint.info;
  info.scene_text = scene.text;
  if (end == now) {
    if (!quiet) std::cout << "carom: " << directory << " is already at t = " << now << " s; nothing to do (use --end)\n";
    return kExitOk;
  }
  StartedRun restored = restore_run(scene, checkpoint, checkpoint_path.string());
  CollisionMethod& sim = *restored.method;
  check_restored_state(sim, scene.method.kind, checkpoint_path.string());
  // A later end (--end) writes more: the whole run's output, estimated as for `carom run`, must
  // fit too, checked before anything is written.
  check_output_size(scene, estimate_output(scene, sim.system().particles.size()), dir);
  checkpoint.file.reset();  // everything is read: the run writes its next checkpoint over it
  RunAnalysis analysis(scene, sim, (dir / "run.h5").string(), now);
  std::unique_ptr<RunFile> file = RunFile::append((dir / "run.h5").string());
  return run_loop(sim, restored.gas.get(), restored.flow.get(), *file, analysis, scene, info, dir, end, false, quiet);
}

}  // namespace carom
