// The `carom` command against what a new user and a hostile input try: inputs that
// are the wrong kind of file, a negative seed, a signal while the bed settles before t = 0, an
// output that would fill the disk, --overwrite over an earlier run's figures, `carom info` as a
// summary, and report.md saying only what applies to the scene.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <thread>

#include "cli_support.hpp"
#include "scenarios/run/output_estimate.hpp"
#include "scenarios/scene/scene.hpp"

namespace fs = std::filesystem;
using namespace carom;
using namespace carom_cli_test;

extern char** environ;

namespace {

/// kSmallGas with one species only (a: d = 1 m, 244 particles) and a mixing analysis.
std::string one_species_gas() {
  std::string text = kSmallGas;
  const std::string b = "[[species]]\nname = \"b\"\ndiameter = 0.6\ndensity = 1.909859317102744\nfill = { count = 100 }\n";
  text.erase(text.find(b), b.size());
  return text + "[analysis]\nmixing = { species = \"a\", cells = [2, 2, 2] }\n";
}

/// The figure names plot.py writes beside RUN.h5 ("energies", "gas", ...): the names in its
/// ("NAME", lambda ...) list and those analysis_plots.py appends.
std::set<std::string> plot_figure_names() {
  const fs::path plots = fs::path(kScenes).parent_path() / "plots";
  std::set<std::string> names;
  const std::regex figure(R"rx(\("([a-z_]+)",\s*lambda)rx");
  for (const char* script : {"plot.py", "analysis_plots.py"}) {
    const std::string text = read(plots / script);
    for (std::sregex_iterator it(text.begin(), text.end(), figure), end; it != end; ++it) names.insert((*it)[1]);
  }
  return names;
}

}  // namespace

// Each of these used to give a message that misled (or a wrong exit code); each now says what
// is wrong, exit 2.
TEST_F(Cli, InputErrorsSayWhatIsWrong) {
  const std::string gas = scene("gas.toml", kSmallGas);
  fs::create_directories(dir_ / "folder");
  EXPECT_EQ(carom("check folder"), 2) << out_;
  EXPECT_NE(out_.find("folder: is a directory, not a scene file"), std::string::npos) << out_;
  scene("sweep.toml", "[sweep]\nscene = \"gas.toml\"\nseeds = [1, 2]\n");
  EXPECT_EQ(carom("check sweep.toml"), 2) << out_;
  EXPECT_NE(out_.find("sweep.toml:1: this is a sweep file"), std::string::npos) << out_;
  EXPECT_NE(out_.find("run it with `carom sweep sweep.toml`"), std::string::npos) << out_;
  EXPECT_EQ(carom("run " + gas + " --seed -1 --out r"), 2) << out_;
  EXPECT_NE(out_.find("--seed -1: a seed must be a non-negative integer"), std::string::npos) << out_;
  EXPECT_EQ(out_.find("18446744073709551615"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "r"));
  EXPECT_EQ(carom("check " + gas + " --seed 7"), 0) << out_;
  EXPECT_NE(out_.find("seed 7"), std::string::npos) << out_;
  // carom info on something that is not a run file: a usage error (2), not a failed run (1).
  EXPECT_EQ(carom("info " + gas), 2) << out_;
  EXPECT_NE(out_.find("gas.toml: not an HDF5 file"), std::string::npos) << out_;
  EXPECT_EQ(carom("info folder"), 2) << out_;
  EXPECT_NE(out_.find("is a directory"), std::string::npos) << out_;
  // The neighbour grid's levels: the default is the cost model, not "-1 x the diameter above".
  EXPECT_EQ(carom("check " + gas), 0) << out_;
  EXPECT_EQ(out_.find("-1 x"), std::string::npos) << out_;
  EXPECT_NE(out_.find("cost model"), std::string::npos) << out_;
  EXPECT_EQ(carom("check " + gas + " --set engine.grid_level_ratio=0.5"), 0) << out_;
  EXPECT_NE(out_.find("a diameter below 0.5 x the largest of a level starts a new level"), std::string::npos) << out_;
}

// SIGTERM while initial.settle_time runs (before t = 0) used to kill carom with no message
// (exit 143). Now: exit 130, a message that nothing was written, and no output directory.
TEST_F(Cli, SignalWhileSettlingExitsInterruptedAndWritesNothing) {
  // An elastic gas settling "for ever" (1e6 s is hours of wall time).
  const std::string gas = scene("gas.toml", kSmallGas);
  const std::string log = (dir_ / "stderr.txt").string();
  std::vector<std::string> args{kCarom, "run", (dir_ / gas).string(), "--out", (dir_ / "s").string(),
                                "--set", "collisions.default={ e = 1.0 }", "--set", "initial.settle_time=1e6"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, kCarom.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  const std::string message = read(log);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << "; "
                                 << message;
  EXPECT_EQ(WEXITSTATUS(status), 130) << message;
  EXPECT_NE(message.find("interrupted while settling ("), std::string::npos) << message;
  EXPECT_NE(message.find("initial.settle_time = 1e+06"), std::string::npos) << message;
  EXPECT_NE(message.find("nothing was written"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir_ / "s")) << "an interrupted settling must leave no output directory";
}

// output.snapshot_every = 1e-9 used to be accepted (31 MB in 8 s, and on). Now refused before
// anything is written; `carom check` prints the estimate; output.max_bytes allows a big run.
TEST_F(Cli, RunawayOutputIsRefusedBeforeAnythingIsWritten) {
  const std::string gas = scene("gas.toml", kSmallGas);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(carom("run " + gas + " --out r --set output.snapshot_every=1e-9"), 2) << out_;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_NE(out_.find("more than output.max_bytes = 10 GB (the default)"), std::string::npos) << out_;
  EXPECT_NE(out_.find("output.snapshot_every = 1e-09 s"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "r"));
  EXPECT_EQ(carom("check " + gas), 0) << out_;
  EXPECT_NE(out_.find("output: about "), std::string::npos) << out_;
  EXPECT_NE(out_.find("9 snapshots of"), std::string::npos) << out_;  // k * 0.5 s up to 4 s
  EXPECT_EQ(carom("check " + gas + " --set output.snapshot_every=1e-9"), 0) << out_;
  EXPECT_NE(out_.find("a run refuses more than 10 GB"), std::string::npos) << out_;
}

// The estimate is near what a run writes: within a factor 1.25 of run.h5, run.xmf and
// checkpoint.h5 together, for a run dominated by snapshot overhead (few particles, many
// snapshots) and for one dominated by particle rows.
TEST_F(Cli, OutputEstimateIsNearTheWrittenSize) {
  const std::string gas = scene("gas.toml", kSmallGas);
  for (const std::string every : {"0.01", "0.5"}) {
    SCOPED_TRACE("snapshot_every = " + every);
    const std::vector<std::string> overrides{"time.end=1.0", "output.snapshot_every=" + every};
    const std::string out = "r" + every;
    ASSERT_EQ(carom("run " + gas + " --quiet --out " + out + " --set time.end=1.0 --set output.snapshot_every=" + every),
              0)
        << out_;
    const std::size_t particles = nlohmann::json::parse(read(dir_ / out / "summary.json"))["particles"];
    const OutputEstimate e = estimate_output(load_scene((dir_ / gas).string(), overrides), particles);
    double written = 0;
    for (const char* name : {"run.h5", "run.xmf", "checkpoint.h5"}) written += double(fs::file_size(dir_ / out / name));
    EXPECT_GT(e.bytes, written / 1.25) << "estimate " << e.bytes << " bytes, written " << written;
    EXPECT_LT(e.bytes, written * 1.25) << "estimate " << e.bytes << " bytes, written " << written;
  }
}

// --overwrite used to leave the earlier run's PNGs beside the new run's outputs. It now removes
// carom's own files (the outputs and every figure plot.py draws, read from plot.py itself) and
// nothing else.
TEST_F(Cli, OverwriteRemovesTheEarlierRunsFigures) {
  const std::string gas = scene("gas.toml", kSmallGas);
  ASSERT_EQ(carom("run " + gas + " --out r --quiet --set time.end=0.5"), 0) << out_;
  const std::set<std::string> figures = plot_figure_names();
  ASSERT_GE(figures.size(), 7u) << "plot.py's figure list not found";
  for (const std::string& name : figures) std::ofstream(dir_ / "r" / ("run_" + name + ".png")) << "old";
  std::ofstream(dir_ / "r" / "notes.txt") << "mine";
  EXPECT_EQ(carom("run " + gas + " --out r --quiet --set time.end=0.5"), 2) << out_;  // refused without it
  ASSERT_EQ(carom("run " + gas + " --out r --quiet --overwrite --set time.end=0.5"), 0) << out_;
  for (const std::string& name : figures)
    EXPECT_FALSE(fs::exists(dir_ / "r" / ("run_" + name + ".png"))) << "run_" << name << ".png left from the old run";
  EXPECT_EQ(read(dir_ / "r" / "notes.txt"), "mine") << "a file carom did not write was touched";
  // Figures alone (outputs removed by hand) still mark the directory as a run's.
  for (const char* name : {"run.h5", "run.xmf", "checkpoint.h5", "summary.json", "report.md"}) fs::remove(dir_ / "r" / name);
  std::ofstream(dir_ / "r" / "run_energies.png") << "old";
  EXPECT_EQ(carom("run " + gas + " --out r --quiet --set time.end=0.5"), 2) << out_;
  EXPECT_NE(out_.find("run_energies.png"), std::string::npos) << out_;
}

// carom info used to dump the raw HDF5 tree; it now says what a person asks first, and --tree
// gives the tree.
TEST_F(Cli, InfoSummarisesARun) {
  const std::string gas = scene("gas.toml", kSmallGas);
  ASSERT_EQ(carom("run " + gas + " --out r --quiet --set time.end=1.0 --seed 3"), 0) << out_;
  ASSERT_EQ(carom("info r/run.h5"), 0) << out_;
  for (const std::string piece : {"r/run.h5: carom run file", "scene \"gas\", carom ", "seed 3",
                                  "species: a: 244 particles of d = 1 m; b: 100 particles of d = 0.6 m",
                                  "snapshots: 3, t = 0 to 1 s", "time series: 11 rows, t = 0 to 1 s",
                                  "status (summary.json): completed", "collision rate per particle (1/s): a-a "})
    EXPECT_NE(out_.find(piece), std::string::npos) << "'" << piece << "' not in:\n" << out_;
  EXPECT_EQ(out_.find("/snapshots/"), std::string::npos) << "the summary lists the raw tree:\n" << out_;
  ASSERT_EQ(carom("info --tree r/run.h5"), 0) << out_;
  EXPECT_NE(out_.find("/snapshots/"), std::string::npos) << out_;
  EXPECT_NE(out_.find("groups, "), std::string::npos) << out_;
  ASSERT_EQ(carom("info r/checkpoint.h5"), 0) << out_;
  EXPECT_NE(out_.find("carom checkpoint file"), std::string::npos) << out_;
  EXPECT_NE(out_.find("state of method event_driven at t = 1 s, 344 particles"), std::string::npos) << out_;
  fs::remove(dir_ / "r" / "summary.json");
  ASSERT_EQ(carom("info r/run.h5"), 0) << out_;
  EXPECT_NE(out_.find("no summary.json beside the file"), std::string::npos) << out_;
}

// report.md of a scene without fines or gas used to carry the fines "Mechanism" paragraph and
// "d = 1000 mm" for a 1 m sphere; it now says only what applies.
TEST_F(Cli, ReportSaysOnlyWhatApplies) {
  const std::string one = scene("one.toml", one_species_gas());
  ASSERT_EQ(carom("run " + one + " --out one --quiet --set time.end=1.0"), 0) << out_;
  const std::string single = read(dir_ / "one" / "report.md");
  EXPECT_NE(single.find("244 a (d = 1 m)"), std::string::npos) << single;
  EXPECT_EQ(single.find("1000 mm"), std::string::npos) << single;
  EXPECT_EQ(single.find("Mechanism"), std::string::npos) << single;
  EXPECT_EQ(single.find("Fines"), std::string::npos) << single;
  EXPECT_NE(single.find("fit of M = 1 - (1 - M0) exp(-k t) from the measured M0 = "), std::string::npos) << single;
  // Two species without a gas or gravity: the collision part only, and no per-weight column.
  const std::string two = scene("two.toml", kSmallGas);
  ASSERT_EQ(carom("run " + two + " --out two --quiet --set time.end=1.0"), 0) << out_;
  const std::string pair = read(dir_ / "two" / "report.md");
  EXPECT_NE(pair.find("## Mechanism"), std::string::npos) << pair;
  EXPECT_NE(pair.find("only through collisions"), std::string::npos) << pair;
  EXPECT_EQ(pair.find("pore volume"), std::string::npos) << pair;
  EXPECT_EQ(pair.find("gas velocity seen"), std::string::npos) << pair;
  EXPECT_EQ(pair.find("weight"), std::string::npos) << pair;
  EXPECT_NE(pair.find("| a-b | "), std::string::npos) << pair;
}
