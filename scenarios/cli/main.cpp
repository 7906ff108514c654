// carom: the command line of the event-driven hard-sphere simulator.
//
// clang-format off
//   carom run SCENE [--set key=value ...] [--out DIR] [--seed N] [--method auto|KIND] [--quiet] [--overwrite]
//   carom resume DIR [--end T] [--quiet]
//   carom check SCENE [--set key=value ...] [--seed N] [--settle]
//   carom info FILE.h5 [--tree]
//   carom sweep SWEEP.toml [--jobs J] [--out DIR] [--retry-failed] [--dry-run] [--quiet]
//   carom chart CHART.toml [--jobs J] [--out DIR] [--retry-failed] [--dry-run] [--quiet]
// clang-format on
//
// Exit codes: 0 ok, 1 runtime failure (inelastic collapse, I/O), 2 bad scene or usage (nothing
// is written), 130 interrupted by SIGINT/SIGTERM (a checkpoint is written). See run.hpp.
#include <CLI/CLI.hpp>
#include <hdf5.h>

#include <filesystem>
#include <iostream>

#include "carom/version.hpp"
#include "scenarios/chart/chart.hpp"
#include "scenarios/cli/check.hpp"
#include "scenarios/cli/info.hpp"
#include "scenarios/cli/recommend.hpp"
#include "scenarios/run/run.hpp"
#include "scenarios/scene/input_file.hpp"
#include "scenarios/scene/overrides.hpp"
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/settling.hpp"
#include "scenarios/sweep/sweep.hpp"
#include "scenarios/sweep/sweep_pool.hpp"

using namespace carom;

namespace {
constexpr const char* kExitCodes =
    "Exit codes: 0 ok; 1 runtime failure (inelastic collapse, I/O error); 2 bad scene or usage (nothing written); "
    "130 interrupted by SIGINT/SIGTERM (checkpoint written; continue with carom resume DIR).";
}

int main(int argc, char** argv) {
  // Every HDF5 handle is closed by its owner before main returns; HDF5's own exit handler would
  // close again what a failed write (a full disk) left half-closed, and crash.
  H5dont_atexit();
  CLI::App app{"carom: event-driven hard-sphere granular simulator"};
  app.footer(kExitCodes);
  app.set_version_flag("--version", std::string("carom ") + kVersion);
  app.require_subcommand(1);

  std::string scene_path, out_dir, resume_dir, info_path;
  std::vector<std::string> overrides;
  std::string seed_text;  // checked by parse_seed: CLI11 would wrap "-1" into 2^64 - 1
  std::string method_choice;
  bool quiet = false, overwrite = false;
  double end_time = 0;

  CLI::App* run = app.add_subcommand("run", "run a scene; writes DIR/run.h5 (+ run.xmf), checkpoint.h5, summary.json");
  run->add_option("scene", scene_path, "scene file (TOML; see scenarios/scenes/SCENES.md)")->required();
  run->add_option("--set", overrides, "change a scene value before validation, e.g. --set collisions.default.e=0.9")
      ->type_name("KEY=VALUE");
  CLI::Option* out_option = run->add_option("--out", out_dir, "output directory (default: SCENE's name + .out)");
  CLI::Option* seed_option = run->add_option("--seed", seed_text, "random seed, an integer >= 0 (replaces initial.seed)");
  run->add_option(
         "--method", method_choice,
         "collision method: auto (what `carom check` recommends), event_driven, soft_sphere or "
         "monte_carlo (replaces method.kind)")
      ->check(CLI::IsMember({"auto", "event_driven", "soft_sphere", "monte_carlo"}));
  run->add_flag("--quiet", quiet, "no progress line and no messages but errors");
  run->add_flag("--overwrite", overwrite, "replace the outputs of an earlier run in DIR");

  CLI::App* resume = app.add_subcommand("resume", "continue a run from DIR/checkpoint.h5, bit for bit");
  resume->add_option("dir", resume_dir, "output directory of the run")->required();
  CLI::Option* end_option = resume->add_option("--end", end_time, "run to this time, s (default: the scene's time.end)");
  resume->add_flag("--quiet", quiet, "no progress line and no messages but errors");

  CLI::App* check = app.add_subcommand("check", "validate a scene and print what it will model; writes nothing");
  check->add_option("scene", scene_path, "scene file")->required();
  check->add_option("--set", overrides, "change a scene value before validation")->type_name("KEY=VALUE");
  CLI::Option* check_seed = check->add_option("--seed", seed_text, "random seed, an integer >= 0");
  bool settle = false;
  check->add_flag("--settle", settle,
                  "run the scene's settling (initial.settle_time) before the estimates; without it the bed is "
                  "taken as settled to a random packing");

  CLI::App* info = app.add_subcommand("info", "describe a run file or checkpoint");
  info->add_option("file", info_path, "HDF5 file (run.h5, checkpoint.h5 or a sweep's summary.h5)")->required();
  bool tree = false;
  info->add_flag("--tree", tree, "list every group and dataset of the file (the raw HDF5 tree)");

  SweepOptions sweep_options;
  std::string sweep_out;
  CLI::App* sweep = app.add_subcommand(
      "sweep", "run a scene over a grid of scene values and seeds, resumably; also under mpirun (see SWEEPS.md)");
  sweep->add_option("sweep_file", sweep_options.file, "sweep file (TOML; see scenarios/sweep/SWEEPS.md)")->required();
  sweep->add_option("--jobs,-j", sweep_options.jobs, "cases run at once (per MPI rank)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{4096}));
  CLI::Option* sweep_out_option = sweep->add_option("--out", sweep_out, "output directory (replaces the file's out)");
  sweep->add_flag("--retry-failed", sweep_options.retry_failed, "run cases that failed before again, from their start");
  sweep->add_flag("--dry-run", sweep_options.dry_run, "validate every case (as carom check) and list them; run nothing");
  sweep->add_flag("--quiet", sweep_options.quiet, "no progress lines (errors are still printed)");
  sweep->footer(
      "Exit codes: 0 every case completed; 1 some case failed (summary still written); 2 bad sweep file or case "
      "(nothing run); 130 interrupted (run the same command again to continue).");

  ChartOptions chart_options;
  std::string chart_out;
  CLI::App* chart = app.add_subcommand(
      "chart", "speed against accuracy: a scene's variants over seeds, error against CPU cost (see CHARTS.md)");
  chart->add_option("chart_file", chart_options.file, "chart file (TOML; see scenarios/chart/CHARTS.md)")->required();
  chart->add_option("--jobs,-j", chart_options.jobs, "cases run at once (per MPI rank)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{4096}));
  CLI::Option* chart_out_option = chart->add_option("--out", chart_out, "output directory (replaces the file's out)");
  chart->add_flag("--retry-failed", chart_options.retry_failed, "run cases that failed before again, from their start");
  chart->add_flag("--dry-run", chart_options.dry_run, "validate every case (as carom check) and list them; run nothing");
  chart->add_flag("--quiet", chart_options.quiet, "no progress lines (errors are still printed)");
  chart->footer(
      "Exit codes: 0 every case completed; 1 some case failed (tables still written); 2 bad chart file or case "
      "(nothing run), or an observable no summary.json holds; 130 interrupted (run the same command again to "
      "continue).");

  if (!follow_sweep_parent()) {
    std::cerr << "carom: the sweep that started this case is gone: not started (run the sweep again)\n";
    return kExitInterrupted;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }

  if (*sweep) {
    if (sweep_out_option->count() > 0) sweep_options.out = sweep_out;
    return run_sweep(sweep_options);
  }
  if (*chart) {
    if (chart_out_option->count() > 0) chart_options.out = chart_out;
    return run_chart(chart_options);
  }
  try {
    if (*run || *check) {
      std::optional<std::uint64_t> chosen_seed;
      if (seed_option->count() > 0 || check_seed->count() > 0) chosen_seed = parse_seed(seed_text);
      if (!method_choice.empty() && method_choice != "auto")
        overrides.push_back("method.kind=" + method_choice);
      Scene scene = load_scene(scene_path, overrides, chosen_seed);
      if (method_choice == "auto") {
        // The recommendation from the placed particles (without the settling run, which would
        // use the scene's method), then the scene again with the recommended method.
        install_stop_handlers();
        Scene placed = scene;
        placed.settle_time = 0;
        build_initial_state(placed, stop_flag());
        if (*stop_flag())
          throw InterruptedBeforeStart(
              "interrupted while the particles were placed: nothing written");
        const std::vector<Advice> advice = recommend(placed, scene_numbers(placed, scene.settle_time > 0));
        const std::string_view chosen = method_name(recommended_method(advice));
        if (!quiet)
          std::cerr << "carom: --method auto: " << chosen << " (" << advice.front().reason << ")\n";
        overrides.push_back("method.kind=" + std::string(chosen));
        scene = load_scene(scene_path, overrides, chosen_seed);
      }
      if (*check) {
        check_scene(std::move(scene), settle, std::cout);
        return kExitOk;
      }
      RunOptions options;
      options.out_dir = out_option->count() > 0 ? out_dir : std::filesystem::path(scene_path).stem().string() + ".out";
      options.quiet = quiet;
      options.overwrite = overwrite;
      return run_scene(std::move(scene), options);
    }
    if (*resume) {
      std::optional<double> end;
      if (end_option->count() > 0) end = end_time;
      return resume_run(resume_dir, end, quiet);
    }
    if (*info) {
      if (tree)
        print_file_tree(info_path, std::cout);
      else
        print_file_info(info_path, std::cout);
      return kExitOk;
    }
  } catch (const InterruptedBeforeStart& e) {
    std::cerr << "carom: " << e.what() << "\n";
    return kExitInterrupted;
  } catch (const SceneError& e) {
    std::cerr << "carom: error: " << shorten_long_tokens(e.what()) << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "carom: failed: " << shorten_long_tokens(e.what()) << "\n";
    return kExitFailure;
  }
  return kExitUsage;
}
