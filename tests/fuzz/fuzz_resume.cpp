// libFuzzer harness: `carom resume` (resume_run, in process) on damaged output folders.
//
// At start-up five short runs are made in a scratch folder, one per seed scene of this folder:
// event-driven (tiny_run.toml), soft spheres (resume_soft_sphere.toml), Monte Carlo
// (resume_monte_carlo.toml), a gas-fluidized bed (resume_gas_bed.toml: event-driven, relax
// flights, two-way gas with an inlet) and an inflow duct (resume_inflow_duct.toml: soft spheres,
// an inflow and an outflow). Each leaves run.h5, checkpoint.h5 (at its end time), run.xmf and
// summary.json. The input picks one of them, how far to resume, whether to seal the damaged
// checkpoint again, and a list of edits to its checkpoint.h5 and to its run.h5 (the edits of
// fuzz_h5_edit.hpp: element bytes, shapes, deleted datasets and attributes, the stored scene
// text). The folder is copied, edited, and resumed for a few steps past the checkpoint.
//
// Resealing matters: the checkpoint's checksum (scenarios/run/file_checksum.hpp) refuses any
// edited checkpoint before a value is used, so without it every edit would stop there. Sealed
// again (7 inputs in 8), the edited values reach what comes after: the run identity, the state
// checks (checkpoint_check.hpp), the method's, gas's and flow's restore, and the run loop.
//
// The answers that are not defects: a SceneError (exit 2: refused, naming file and dataset); a
// runtime error out of resume_run (exit 1, "carom: failed: ..."); a return of 0 (resumed); a
// return of 1 with summary.json saying why (a detector: inelastic_collapse, stalled, a method's
// failure status; or "failed" on an output error naming run.h5 (or "run file") or
// checkpoint.h5, the damaged files it appends to), or without summary.json where that error
// kept it from being written (carom says so on stderr; the seed's summary.json is removed from
// the copy first). Anything else aborts so that libFuzzer keeps the input: a crash or a
// sanitizer report, a logic_error, bad_alloc or non-standard exception, a return of 130 or
// another code, status "failed" for anything but those files and a method's own checks of its
// state ("must be finite", the gas solver's divergence), and a resume that runs longer
// than kHangSeconds (a watchdog thread: the run loop's stall timer takes SIGALRM, which
// libFuzzer's -timeout uses too, so the harness restores libFuzzer's handler and timer after
// each resume).
// CAROM_FUZZ_VERBOSE=1 prints the edits and the outcome of each input.
#include <fuzzer/FuzzedDataProvider.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/time.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/hdf5.hpp"
#include "scenarios/run/file_checksum.hpp"
#include "scenarios/run/run.hpp"
#include "scenarios/scene/scene.hpp"
#include "tests/fuzz/fuzz_h5_edit.hpp"
#include "tests/fuzz/fuzz_initial_support.hpp"

namespace {

namespace fs = std::filesystem;
using carom::fuzz::SeedFile;

/// A resume that takes longer than this (wall seconds, under the sanitizers) is a hang; below
/// run.sh's -timeout of 20 s, which the run loop's own SIGALRM timer suspends.
constexpr double kHangSeconds = 15.0;

/// One seed run: its scene, how far a resume goes past its checkpoint, and its files.
struct SeedRun {
  const char* name = "";
  const char* scene = "";  ///< In tests/fuzz.
  double step = 0;         ///< Simulated seconds per unit of the input's resume length (1 to 4).
  fs::path folder;         ///< The run's output folder (kept unchanged).
  double end_time = 0;
  SeedFile run;
  SeedFile checkpoint;
};

struct Seeds {
  fs::path work_dir;
  std::vector<SeedRun> runs;
};

std::atomic<double> g_input_started{0};  // steady-clock seconds; 0 between inputs
std::atomic<bool> g_watchdog_on{false};

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void start_watchdog() {
  if (g_watchdog_on.exchange(true)) return;
  std::thread([] {
    for (;;) {
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
      const double started = g_input_started.load();
      if (started > 0 && now_seconds() - started > kHangSeconds) {
        std::fprintf(stderr, "carom fuzz: resume still running after %.0f s: a hang\n",
                     kHangSeconds);
        std::abort();
      }
    }
  }).detach();
}

Seeds make_seeds() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // damaged files: HDF5's errors are expected
  // One thread (the tiny runs do not use more); the stall watch looks every second instead of
  // every 60 s, so that a state that stops the simulated time is ended by carom, not the watchdog.
  setenv("CAROM_THREADS", "1", 1);
  setenv("CAROM_STALL_WINDOW_SECONDS", "1", 1);
  Seeds seeds;
  const std::string folder = carom::fuzz::make_work_dir("carom_fuzz_resume");
  seeds.work_dir = folder;
  const struct {
    const char* name;
    const char* scene;
    double step;
  } cases[] = {{"event_driven", "tiny_run.toml", 0.002},
               {"soft_sphere", "resume_soft_sphere.toml", 0.0002},
               {"monte_carlo", "resume_monte_carlo.toml", 0.001},
               {"gas_bed", "resume_gas_bed.toml", 0.0005},
               {"inflow_duct", "resume_inflow_duct.toml", 0.001}};
  for (const auto& c : cases) {
    SeedRun run;
    run.name = c.name;
    run.scene = c.scene;
    run.step = c.step;
    seeds.runs.push_back(std::move(run));
  }
  for (SeedRun& run : seeds.runs) {
    const fs::path scene_path = fs::path(CAROM_FUZZ_DIR) / run.scene;
    carom::Scene scene = carom::load_scene(scene_path.string());
    run.end_time = scene.end_time;
    carom::RunOptions options;
    run.folder = fs::path(folder) / ("seed_" + std::string(run.name));
    options.out_dir = run.folder.string();
    options.quiet = true;
    if (carom::run_scene(std::move(scene), options) != carom::kExitOk) {
      std::fprintf(stderr, "carom fuzz: the seed run of %s failed\n", scene_path.c_str());
      std::abort();
    }
    run.run = carom::fuzz::load_seed_file((run.folder / "run.h5").string());
    run.checkpoint = carom::fuzz::load_seed_file((run.folder / "checkpoint.h5").string());
  }
  start_watchdog();
  return seeds;
}

const Seeds& seeds() {
  static const Seeds made = make_seeds();
  return made;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The value of "key": "..." in summary.json (its top-level status and message are the first).
std::string json_string_value(const std::string& json, const std::string& key) {
  const std::string marker = "\"" + key + "\": \"";
  const std::size_t at = json.find(marker);
  if (at == std::string::npos) return "";
  std::string value;
  for (std::size_t k = at + marker.size(); k < json.size() && json[k] != '"'; ++k) {
    if (json[k] == '\\' && k + 1 < json.size()) ++k;
    value += json[k];
  }
  return value;
}

[[noreturn]] void defect(const std::string& what) {
  std::fprintf(stderr, "carom fuzz: %s\n", what.c_str());
  std::abort();
}

/// libFuzzer's handlers and timer, which the run loop replaces (SIGINT/SIGTERM for its clean stop,
/// SIGALRM for its stall watch) and leaves off when it returns.
struct SavedSignals {
  struct sigaction interrupt {
  }, terminate{}, alarm{};
  itimerval timer{};
  SavedSignals() {
    sigaction(SIGINT, nullptr, &interrupt);
    sigaction(SIGTERM, nullptr, &terminate);
    sigaction(SIGALRM, nullptr, &alarm);
    getitimer(ITIMER_REAL, &timer);
  }
  ~SavedSignals() {
    sigaction(SIGINT, &interrupt, nullptr);
    sigaction(SIGTERM, &terminate, nullptr);
    sigaction(SIGALRM, &alarm, nullptr);
    setitimer(ITIMER_REAL, &timer, nullptr);
  }
};

/// Runs resume_run on `dir` and aborts on anything but a clean refusal, a clean failure or a
/// successful resume (the header comment).
void resume_like_carom(const fs::path& dir, std::optional<double> end, bool verbose) {
  int code = -1;
  {
    const SavedSignals saved;
    g_input_started = now_seconds();
    try {
      code = carom::resume_run(dir.string(), end, true);
    } catch (const carom::SceneError& e) {
      g_input_started = 0;
      if (verbose) std::fprintf(stderr, "outcome: refused (exit 2): %s\n", e.what());
      return;
    } catch (const std::logic_error& e) {
      defect(std::string("a logic_error out of resume_run (a bug, not a refusal): ") + e.what());
    } catch (const std::bad_alloc& e) {
      defect(std::string("bad_alloc out of resume_run: ") + e.what());
    } catch (const std::runtime_error& e) {
      g_input_started = 0;
      if (verbose) std::fprintf(stderr, "outcome: failed (exit 1): %s\n", e.what());
      return;
    } catch (const std::exception& e) {
      defect(std::string("an unexpected exception out of resume_run: ") + e.what());
    } catch (...) {
      defect("a non-standard exception out of resume_run");
    }
    g_input_started = 0;
  }
  if (code == carom::kExitOk) {
    if (verbose) std::fprintf(stderr, "outcome: resumed (exit 0)\n");
    return;
  }
  if (code != carom::kExitFailure) defect("resume_run returned " + std::to_string(code));
  // A failure that also keeps summary.json from being written (a damaged run.h5 whose waiting
  // rows cannot be appended) says so on stderr: a clean exit 1 too.
  if (!fs::exists(dir / "summary.json")) {
    if (verbose) std::fprintf(stderr, "outcome: exit 1, summary.json not written\n");
    return;
  }
  const std::string summary = read_text(dir / "summary.json");
  const std::string status = json_string_value(summary, "status");
  const std::string message = json_string_value(summary, "message");
  if (verbose)
    std::fprintf(stderr, "outcome: exit 1, status %s: %s\n", status.c_str(), message.c_str());
  if (status.empty() || status == "completed" || status == "interrupted")
    defect("resume_run returned 1 with summary.json status '" + status + "'");
  // "failed" is the run loop's answer to an exception it did not expect: in this harness only an
  // output it cannot append to (the damaged run.h5, "run file: ...", the checkpoint) is one, or
  // a method's own check of its state, which names the quantity that "must be finite" or the gas
  // solver's divergence check (a gas field damaged under a re-sealed checksum within the restore
  // checks' bounds, e.g. a face velocity of 1e4 m/s, makes the solver diverge at its first fluid
  // step, which stops the run with exit 1: a blow-up detected and explained, not a refusal).
  if (status == "failed" && message.find("run.h5") == std::string::npos &&
      message.find("run file") == std::string::npos &&
      message.find("checkpoint.h5") == std::string::npos &&
      message.find("must be finite") == std::string::npos &&
      message.find("gas solver: the velocities diverged") == std::string::npos)
    defect("the resumed run failed on something other than its output files: " + message);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  seeds();  // the five seed runs, once
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool verbose = std::getenv("CAROM_FUZZ_VERBOSE") != nullptr;
  const Seeds& all = seeds();
  FuzzedDataProvider input(data, size);
  const SeedRun& seed = all.runs[input.ConsumeIntegralInRange<std::size_t>(0, all.runs.size() - 1)];
  // 0: no --end (the scene's end, which is the checkpoint's time: nothing to do); 1-4 steps.
  const int length = input.ConsumeIntegralInRange(0, 4);
  const bool reseal = input.ConsumeIntegralInRange(0, 7) != 0;
  std::optional<double> end;
  if (length > 0) end = seed.end_time + length * seed.step;
  if (verbose)
    std::fprintf(stderr, "seed %s, end %s, %s\n", seed.name,
                 end ? std::to_string(*end).c_str() : "(scene's)",
                 reseal ? "checkpoint sealed again" : "checkpoint not sealed again");

  const fs::path dir = all.work_dir / "resume";
  std::error_code error;
  fs::remove_all(dir, error);
  fs::copy(seed.folder, dir, fs::copy_options::recursive, error);
  if (error) defect("cannot copy the seed run: " + error.message());
  // The seed's summary.json says "completed": removed, so that what the resume writes is read.
  fs::remove(dir / "summary.json", error);
  const std::string checkpoint_path = (dir / "checkpoint.h5").string();
  if (verbose) std::fprintf(stderr, "checkpoint.h5:\n");
  carom::fuzz::write_edited(seed.checkpoint, checkpoint_path, input, 6);
  if (verbose) std::fprintf(stderr, "run.h5:\n");
  carom::fuzz::write_edited(seed.run, (dir / "run.h5").string(), input, 3);
  if (reseal) {
    try {
      carom::seal_file(carom::h5::File::open(checkpoint_path, true));
    } catch (const std::exception& e) {
      if (verbose) std::fprintf(stderr, "not sealed again: %s\n", e.what());
    }
  }
  resume_like_carom(dir, end, verbose);
  return 0;
}
