#include "scenarios/sweep/sweep.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "scenarios/run/output_estimate.hpp"
#include "scenarios/run/run.hpp"
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/settling.hpp"
#include "scenarios/sweep/sweep_case.hpp"
#include "scenarios/sweep/sweep_mpi.hpp"
#include "scenarios/sweep/sweep_pool.hpp"
#include "scenarios/sweep/sweep_report.hpp"
#include "scenarios/sweep/sweep_spec.hpp"
#include "scenarios/sweep/sweep_table.hpp"

namespace carom {

namespace fs = std::filesystem;

namespace {

/// A case as the user would run it by hand, for messages.
std::string describe_case(const SweepSpec& spec, const SweepCase& c) {
  const std::string group = spec.describe_group(c.group);
  return (group.empty() ? std::string() : group + ", ") + "seed " + std::to_string(c.seed);
}

/// The checks a run makes before it starts: the output's size (against the case's folder), the
/// placement (which a stop signal interrupts: InterruptedBeforeStart) and the method's own.
/// Throws SceneError.
void check_case(const SweepSpec& spec, const SweepCase& c) {
  Scene scene = load_scene(spec.scene, c.overrides, c.seed, c.origins);
  try {
    check_output_size(scene, estimate_output(scene, planned_particle_count(scene)),
                      case_directory(spec.out, c.index));
    // Placed and checked as `carom check` does: without the settling run, which is the case's
    // own first stretch (a failure there is the case's, recorded like any other) and would
    // otherwise be run twice, once here for every case before any case starts.
    scene.settle_time = 0;
    build_initial_state(scene, sweep_stop_flag());
    make_method(scene.system, scene.method);  // the checks a run makes at its start
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": " + e.what());
  } catch (const SceneError&) {
    throw;
  } catch (const InterruptedBeforeStart&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(scene.file + ": " + e.what());
  }
}

/// Holds an exclusive lock on OUT/.lock while it lives: two sweeps must not share an OUT.
class OutLock {
 public:
  explicit OutLock(const std::string& out) {
    fs::create_directories(out);
    const std::string path = (fs::path(out) / ".lock").string();
    fd_ = open(path.c_str(), O_RDWR | O_CREAT, 0644);
    if (fd_ < 0)
      throw SceneError(out + ": cannot create " + path + " (is the directory writable?)");
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0)
      throw SceneError(
          out + " is in use by another carom sweep; wait for it, or give this one another `out`");
  }
  ~OutLock() { close(fd_); }
  OutLock(const OutLock&) = delete;
  OutLock& operator=(const OutLock&) = delete;

 private:
  int fd_ = -1;
};

/// Runs `errors` as a stage on every rank: a SceneError on any rank ends the sweep with exit 2
/// on all of them. `print`: whether this rank prints the error (stages every rank does alike
/// print on rank 0 only).
template <class Stage>
int stage(const SweepRanks& ranks, bool print, const std::string& command, Stage&& body) {
  int code = 0;
  try {
    body();
  } catch (const InterruptedBeforeStart& e) {
    if (print) std::cerr << "carom sweep: " << e.what() << "\n";
    code = kExitInterrupted;
  } catch (const SceneError& e) {
    if (print) std::cerr << command << ": error: " << e.what() << "\n";
    code = kExitUsage;
  } catch (const std::exception& e) {
    if (print) std::cerr << command << ": failed: " << e.what() << "\n";
    code = kExitFailure;
  }
  return ranks.max(code);
}

/// The command line of a case's next attempt.
std::vector<std::string> case_command(const SweepSpec& spec, const SweepCase& c,
                                      const std::string& dir, CaseAction action) {
  if (action == CaseAction::Resume) return {"resume", dir, "--quiet"};
  std::vector<std::string> args{"run", fs::absolute(spec.scene).string()};
  for (const std::string& o : c.overrides) args.insert(args.end(), {"--set", o});
  args.insert(args.end(),
              {"--seed", std::to_string(c.seed), "--out", dir, "--quiet", "--overwrite"});
  return args;
}

int sweep(const SweepOptions& options, const SweepRanks& ranks) {
  const bool leader = ranks.leader();
  SweepSpec spec;
  std::vector<SweepCase> cases;
  std::vector<std::string> digests;
  // 1. The sweep file and every case's scene, parsed (cheap; the same on every rank).
  int code = stage(ranks, leader, options.command, [&] {
    spec = options.spec ? *options.spec : read_sweep(options.file);
    if (options.out) spec.out = *options.out;
    if (spec.seeds.empty()) spec.seeds = {load_scene(spec.scene, spec.fixed, std::nullopt, spec.fixed_origins).seed};
    cases = spec.cases();
    std::string errors;
    for (const SweepCase& c : cases) {
      try {
        digests.push_back(scene_digest(load_scene(spec.scene, c.overrides, c.seed, c.origins).text));
      } catch (const SceneError& e) {
        errors += "\n  case " + std::to_string(c.index) + " (" + describe_case(spec, c) +
                  "): " + e.what();
      }
    }
    if (!errors.empty()) throw SceneError(spec.file + ": some cases make a bad scene:" + errors);
    for (const SweepCase& c : cases)
      check_case_record(case_directory(spec.out, c.index), c, digests[c.index], spec.out);
  });
  if (code != 0) return code;

  // 2. What each case needs; the cases to do, dealt out round-robin over the ranks.
  std::vector<CaseAction> actions;
  std::vector<std::size_t> todo, mine;
  code = stage(ranks, leader, options.command, [&] {
    for (const SweepCase& c : cases) {
      actions.push_back(next_action(case_directory(spec.out, c.index), options.retry_failed));
      if (options.dry_run || actions.back() != CaseAction::Skip) todo.push_back(c.index);
    }
    for (std::size_t k = 0; k < todo.size(); ++k)
      if (k % static_cast<std::size_t>(ranks.size()) == static_cast<std::size_t>(ranks.rank()))
        mine.push_back(todo[k]);
  });
  if (code != 0) return code;

  // 3. Particles placed for every case about to start from scratch, before anything runs.
  code = stage(ranks, true, options.command, [&] {
    std::string errors;
    for (const std::size_t i : mine) {
      if (!options.dry_run && actions[i] != CaseAction::Run) continue;
      if (sweep_stop_requested())
        throw InterruptedBeforeStart("interrupted while the cases were checked (case " +
                                     std::to_string(i) + " of " + std::to_string(cases.size()) +
                                     "): nothing was run");
      try {
        check_case(spec, cases[i]);
      } catch (const SceneError& e) {
        errors += "\n  case " + std::to_string(i) + " (" + describe_case(spec, cases[i]) +
                  "): " + e.what();
      }
    }
    if (!errors.empty()) throw SceneError(spec.file + ": some cases make a bad scene:" + errors);
  });
  if (code != 0 || options.dry_run) {
    if (code == 0 && leader && !options.quiet) {
      std::cout << options.command << ": " << cases.size() << " cases, all valid:\n";
      for (const SweepCase& c : cases)
        std::cout << "  case " << c.index << ": " << describe_case(spec, c) << "\n";
    }
    return code;
  }

  // 4. The output directory (rank 0), then the cases.
  std::optional<OutLock> lock;
  code = stage(ranks, true, options.command, [&] {
    if (!leader) return;
    lock.emplace(spec.out);
    const fs::path copy = fs::path(spec.out) / options.record_name;
    if (!fs::exists(copy) || !fs::equivalent(spec.file, copy))
      fs::copy_file(spec.file, copy, fs::copy_options::overwrite_existing);
    for (const SweepCase& c : cases)
      write_case_record(case_directory(spec.out, c.index), c, digests[c.index],
                        fs::absolute(spec.scene).string());
  });
  if (code != 0) return code;
  if (leader && !options.quiet) {
    const std::size_t resumed =
        static_cast<std::size_t>(std::count(actions.begin(), actions.end(), CaseAction::Resume));
    std::cout << options.command << ": " << cases.size() << " cases, " << cases.size() - todo.size()
              << " already done, " << todo.size() << " to run (" << resumed << " to resume) on "
              << ranks.size() << " rank(s) x " << options.jobs << " job(s); outputs in " << spec.out
              << std::endl;
  }
  const std::string prefix =
      ranks.size() > 1 ? options.command + " [rank " + std::to_string(ranks.rank()) + "]: "
                       : options.command + ": ";
  code = stage(ranks, true, options.command, [&] {
    ProcessPool pool(options.jobs);
    std::size_t next = 0, finished = 0;
    std::vector<CaseResult> before(cases.size());
    for (;;) {
      while (!sweep_stop_requested() && next < mine.size() && pool.has_free_slot()) {
        const std::size_t i = mine[next++];
        const std::string dir = case_directory(spec.out, i);
        before[i] = read_case_result(dir);
        std::ofstream((fs::path(dir) / "log.txt").string(), std::ios::app)
            << "# carom sweep: attempt " << before[i].attempts + 1
            << (actions[i] == CaseAction::Resume ? " (resume)" : "") << "\n";
        pool.start(i, case_command(spec, cases[i], dir, actions[i]),
                   (fs::path(dir) / "log.txt").string());
      }
      const std::optional<ChildExit> exit = pool.wait();
      if (!exit) break;
      const std::size_t i = exit->tag;
      const std::string dir = case_directory(spec.out, i);
      const CaseResult result =
          attempt_result(dir, before[i], exit->exit_code, exit->signal, exit->asked_to_stop,
                         exit->wall_seconds, ranks.rank(), exit->cpu_seconds);
      write_case_result(dir, result);
      ++finished;
      if (!options.quiet) {
        std::ostringstream line;
        line << prefix << "[" << finished << "/" << mine.size() << "] case " << i << " "
             << result.status << " in " << format_number(std::round(exit->wall_seconds * 100) / 100)
             << " s (" << describe_case(spec, cases[i]) << ")";
        if (result.status != "completed" && !result.message.empty()) line << ": " << result.message;
        std::cout << line.str() << std::endl;
      }
    }
  });
  const int interrupted = ranks.max(sweep_stop_requested() ? 1 : 0);

  // 5. The summary, by rank 0 from every case's directory.
  int outcome = code != 0 ? code : kExitOk;
  if (leader) {
    try {
      const SweepTable table = gather_sweep(spec, cases);
      write_sweep_summary(spec, table);
      std::size_t completed = 0;
      for (const CaseRow& row : table.cases) completed += row.result.status == "completed" ? 1 : 0;
      if (completed < cases.size() && outcome == kExitOk) outcome = kExitFailure;
      if (!options.quiet || completed < cases.size())
        std::cout << options.command << ": " << completed << " of " << cases.size() << " cases completed"
                  << (interrupted ? " (interrupted; run the same command again to continue)" : "")
                  << "; summary in " << (fs::path(spec.out) / "summary.csv").string() << std::endl;
    } catch (const std::exception& e) {
      std::cerr << options.command << ": failed to write the summary: " << e.what() << "\n";
      outcome = kExitFailure;
    }
  }
  if (interrupted) outcome = kExitInterrupted;
  return ranks.broadcast(outcome);
}

}  // namespace

int run_sweep(const SweepOptions& options) {
  try {
    SweepRanks ranks;
    install_sweep_signal_handlers();
    return sweep(options, ranks);
  } catch (const SceneError& e) {
    if (first_launched_process()) std::cerr << options.command << ": error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << options.command << ": failed: " << e.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace carom
