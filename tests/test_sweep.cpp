// `carom sweep`, run as a user runs it: a local pool, a failing case, an interrupted sweep
// resumed, the same sweep under mpirun, and mistakes in the sweep file. The runs are
// deterministic (same scene, overrides and seed give the same numbers bit for bit), so
// gathered results are compared exactly, except the few wall-clock measurements.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "core/hdf5.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;

extern char** environ;

// A named namespace, not an anonymous one: the fixture Sweep is a base of the tests' classes,
// which GCC wants to share its linkage when the file is compiled within a unity batch.
namespace carom_sweep_test {

const std::string kCarom = CAROM_BINARY;
const std::string kGas = std::string(CAROM_SWEEP_DATA) + "/gas.toml";

/// Metrics that measure wall-clock time: they differ between any two runs.
const std::set<std::string> kWallClock = {"elapsed_seconds", "wall_seconds", "events_per_second",
                                          "collisions_per_second",
                                          "simulated_seconds_per_wall_second"};

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A CSV file: header and rows of cells (quoted cells unquoted).
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << "no column " << name;
    return static_cast<std::size_t>(it - header.begin());
  }
  std::string at(std::size_t row, const std::string& name) const {
    return rows.at(row).at(column(name));
  }
};

Csv read_csv(const fs::path& path) {
  Csv csv;
  std::istringstream in(read(path));
  std::vector<std::vector<std::string>> lines;
  std::vector<std::string> cells{""};
  bool quoted = false;
  char c;
  while (in.get(c)) {
    if (quoted) {
      if (c == '"' && in.peek() == '"')
        cells.back() += static_cast<char>(in.get());
      else if (c == '"')
        quoted = false;
      else
        cells.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else if (c == '\n') {
      lines.push_back(cells);
      cells = {""};
    } else {
      cells.back() += c;
    }
  }
  if (!lines.empty()) {
    csv.header = lines.front();
    csv.rows.assign(lines.begin() + 1, lines.end());
  }
  return csv;
}

/// Every numeric leaf of a JSON document, dotted (the test's own oracle of the gathering).
void flatten(const Json& node, const std::string& path, std::map<std::string, double>& out) {
  if (node.is_number())
    out[path] = node.get<double>();
  else if (node.is_object())
    for (const auto& [key, value] : node.items())
      flatten(value, path.empty() ? key : path + "." + key, out);
  else if (node.is_array())
    for (std::size_t k = 0; k < node.size(); ++k)
      flatten(node[k], path + "." + std::to_string(k), out);
}

std::map<std::string, double> case_metrics(const fs::path& case_dir) {
  std::map<std::string, double> out;
  flatten(Json::parse(read(case_dir / "summary.json")), "", out);
  return out;
}

Json case_result(const fs::path& case_dir) {
  return Json::parse(read(case_dir / "result.json"));
}

/// A fresh directory per test, removed afterwards.
class Sweep : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("carom_sweep_" + std::to_string(getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Runs `PREFIX carom ARGS` in the test directory; returns the exit code; output in out_.
  int carom(const std::string& args, const std::string& prefix = "") {
    const std::string log = (dir_ / "log.txt").string();
    // timeout: a hang fails the test (exit 124/137) instead of stalling the suite.
    const std::string command = "cd '" + dir_.string() + "' && timeout -k 5 60 " + prefix + " '" +
                                kCarom + "' " + args + " > '" + log + "' 2>&1";
    const int status = std::system(command.c_str());
    out_ = read(log);
    fs::remove(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  /// Writes a file into the test directory; returns its name.
  std::string file(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return name;
  }

  fs::path dir_;
  std::string out_;
};

/// Two restitutions x two seeds, 2 s of a 344-sphere gas each (about 0.1 s of wall time).
const std::string kGrid = "[sweep]\nscene = \"" + kGas +
                          "\"\nseeds = [1, 2]\nset = { \"time.end\" = 2.0 }\n"
                          "[[sweep.vary]]\nkey = \"collisions.default.e\"\nvalues = [0.9, 1.0]\n";

/// Every non-wall-clock cell of two summary.csv files is the same (same rows, same columns).
void expect_same_results(const Csv& a, const Csv& b) {
  ASSERT_EQ(a.header, b.header);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (std::size_t r = 0; r < a.rows.size(); ++r)
    for (std::size_t c = 0; c < a.header.size(); ++c)
      if (!kWallClock.count(a.header[c]) && a.header[c] != "attempts") {
        EXPECT_EQ(a.rows[r][c], b.rows[r][c]) << "row " << r << ", column " << a.header[c];
      }
}

}  // namespace carom_sweep_test

using namespace carom_sweep_test;

// A local pool of 2 over 2 x 2 cases: every case completes once; summary.csv holds one row per
// case with every numeric leaf of its summary.json; the group table's mean and sample standard
// deviation are those of the case summaries (computed here independently, same formula, so
// they agree to round-off: 1e-12 relative).
TEST_F(Sweep, LocalPoolRunsEveryCaseAndAveragesOverSeeds) {
  file("grid.toml", kGrid);
  ASSERT_EQ(carom("sweep grid.toml --jobs 2"), 0) << out_;
  const fs::path out = dir_ / "grid.out";
  const Csv cases = read_csv(out / "summary.csv");
  ASSERT_EQ(cases.rows.size(), 4u) << read(out / "summary.csv");
  const std::vector<std::string> leading{"case",   "group",     "collisions.default.e", "seed",
                                         "status", "exit_code", "elapsed_seconds",      "attempts"};
  ASSERT_GE(cases.header.size(), leading.size());
  EXPECT_EQ(std::vector<std::string>(cases.header.begin(), cases.header.begin() + 8), leading);
  EXPECT_EQ(cases.header.back(), "message");

  std::vector<std::map<std::string, double>> metrics;
  for (std::size_t k = 0; k < 4; ++k) {
    const fs::path case_dir = out / "cases" / ("000" + std::to_string(k));
    EXPECT_EQ(cases.at(k, "case"), std::to_string(k));
    EXPECT_EQ(cases.at(k, "seed"), k % 2 == 0 ? "1" : "2");
    EXPECT_EQ(cases.at(k, "collisions.default.e"), k < 2 ? "0.9" : "1.0");
    EXPECT_EQ(cases.at(k, "status"), "completed");
    EXPECT_EQ(case_result(case_dir)["attempts"], 1);
    metrics.push_back(case_metrics(case_dir));
    ASSERT_GT(metrics.back().size(), 20u);
    ASSERT_TRUE(metrics.back().count("collision_rate_per_particle.a-b"));
    for (const auto& [name, value] : metrics.back())  // every leaf gathered, exactly
      EXPECT_EQ(std::stod(cases.at(k, name)), value) << "case " << k << ": " << name;
  }

  const Csv groups = read_csv(out / "summary_by_group.csv");
  ASSERT_EQ(groups.rows.size(), 2u);
  for (std::size_t g = 0; g < 2; ++g) {
    EXPECT_EQ(groups.at(g, "n_completed"), "2");
    for (const auto& [name, first] : metrics[2 * g]) {
      const double second = metrics[2 * g + 1].at(name);
      const double mean = (first + second) / 2;
      const double std =
          std::sqrt(((first - mean) * (first - mean) + (second - mean) * (second - mean)) / 1.0);
      EXPECT_NEAR(std::stod(groups.at(g, name + ":mean")), mean, 1e-12 * std::abs(mean)) << name;
      EXPECT_NEAR(std::stod(groups.at(g, name + ":std")), std, 1e-12 * std::abs(mean) + 1e-300)
          << name;
    }
  }

  // The HDF5 file holds the same tables, one dataset per column.
  const auto h5 = carom::h5::File::open((out / "summary.h5").string(), false);
  EXPECT_EQ(h5.read_strings("varied_keys"), std::vector<std::string>{"collisions.default.e"});
  EXPECT_EQ(h5.open_group("cases").read_strings("status"),
            std::vector<std::string>(4, "completed"));
  EXPECT_EQ(h5.open_group("cases").read<double>("collisions.default.e"),
            (std::vector<double>{0.9, 0.9, 1.0, 1.0}));
  const auto mean = h5.open_group("groups").open_group("mean").read<double>("energy.dissipated");
  ASSERT_EQ(mean.size(), 2u);
  EXPECT_EQ(mean[1], std::stod(groups.at(1, "energy.dissipated:mean")));
}

// One case collapses (3 collisions of one particle within 1000 s is called a collapse): it is
// recorded with its status, exit code and the reason from its log, the other case completes,
// the sweep exits 1. A second sweep does not retry it; --retry-failed does.
TEST_F(Sweep, FailingCaseIsRecordedAndTheOthersComplete) {
  file(
      "fail.toml",
      "[sweep]\nscene = \"" + kGas +
          "\"\nseeds = [1]\n[sweep.set]\ntime.end = 2.0\ncollisions.collapse.stall_collisions = 2\n"
          "[[sweep.vary]]\nkey = \"collisions.collapse.stall_window\"\nvalues = [0.0, 1000.0]\n");
  ASSERT_EQ(carom("sweep fail.toml --jobs 2"), 1) << out_;
  const Csv cases = read_csv(dir_ / "fail.out" / "summary.csv");
  ASSERT_EQ(cases.rows.size(), 2u);
  EXPECT_EQ(cases.at(0, "status"), "completed");
  EXPECT_EQ(cases.at(1, "status"), "inelastic_collapse");
  EXPECT_EQ(cases.at(1, "exit_code"), "1");
  EXPECT_NE(cases.at(1, "message").find("inelastic collapse"), std::string::npos)
      << cases.at(1, "message");
  EXPECT_NE(out_.find("case 1 inelastic_collapse"), std::string::npos) << out_;
  const Csv groups = read_csv(dir_ / "fail.out" / "summary_by_group.csv");
  EXPECT_EQ(groups.at(1, "n_completed"), "0");
  EXPECT_EQ(groups.at(1, "events:mean"), "") << "a failed case must not enter the statistics";

  ASSERT_EQ(carom("sweep fail.toml"), 1) << out_;
  EXPECT_EQ(case_result(dir_ / "fail.out" / "cases" / "0001")["attempts"], 1)
      << "a failed case was retried";
  ASSERT_EQ(carom("sweep fail.toml --retry-failed"), 1) << out_;
  EXPECT_EQ(case_result(dir_ / "fail.out" / "cases" / "0001")["attempts"], 2)
      << "--retry-failed did not retry";
  EXPECT_EQ(case_result(dir_ / "fail.out" / "cases" / "0000")["attempts"], 1)
      << "a completed case was rerun";
}

// The check before the runs places every case as `carom check` does, without its settling run:
// a case whose settling run fails is recorded as that case's failure and the other completes
// (before, every case's settling ran once in the check and again in its run, and one failing
// settle refused the whole sweep).
TEST_F(Sweep, SettlingRunsOnlyInTheirCases) {
  file("settle.toml",
       "[sweep]\nscene = \"" + kGas +
           "\"\nseeds = [1]\n[sweep.set]\ntime.end = 0.5\ninitial.settle_time = 2.0\n"
           "collisions.collapse.stall_collisions = 2\n"
           "[[sweep.vary]]\nkey = \"collisions.collapse.stall_window\"\nvalues = [0.0, 1000.0]\n");
  ASSERT_EQ(carom("sweep settle.toml --dry-run"), 0) << out_;
  ASSERT_EQ(carom("sweep settle.toml --jobs 2"), 1) << out_;
  const Csv cases = read_csv(dir_ / "settle.out" / "summary.csv");
  ASSERT_EQ(cases.rows.size(), 2u);
  EXPECT_EQ(cases.at(0, "status"), "completed");
  EXPECT_NE(cases.at(1, "status"), "completed");
  EXPECT_NE(case_result(dir_ / "settle.out" / "cases" / "0001")["message"].get<std::string>().find(
                "settl"),
            std::string::npos)
      << case_result(dir_ / "settle.out" / "cases" / "0001");
}

// SIGINT to a sweep while its second case runs: exit 130, that case checkpointed, the third
// never started. The same command again: the first case is not rerun (its summary.json is
// byte for byte the same), the second is resumed from its checkpoint, the third runs, and the
// results equal those of a sweep that was never interrupted. For the resumed case, summary.json
// describes only the resumed stretch (rates and counts since the checkpoint, summary.hpp), so
// there only the whole-run quantities are compared: final time, totals, final energies and the
// analysis (collision frequencies, temperatures: always from t = 0).
TEST_F(Sweep, InterruptedSweepResumesToTheSameResults) {
  file("long.toml",
       "[sweep]\nscene = \"" + kGas +
           "\"\nseeds = [1, 2, 3]\n[sweep.set]\ntime.end = 400.0\n"
           "collisions.default = { e = 1.0, mu = 0.0, beta0 = -1.0 }\n"  // elastic: about 1 s each
           "output.snapshot_every = 100.0\noutput.sample_every = 10.0\noutput.checkpoint_every = "
           "100.0\n");
  pid_t pid = 0;
  std::vector<std::string> args{kCarom, "sweep", "long.toml"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, (dir_ / "first.txt").c_str(),
                                   O_WRONLY | O_CREAT, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  const fs::path cwd = fs::current_path();
  fs::current_path(dir_);
  ASSERT_EQ(posix_spawn(&pid, kCarom.c_str(), &actions, nullptr, argv.data(), environ), 0);
  fs::current_path(cwd);
  posix_spawn_file_actions_destroy(&actions);
  const fs::path out = dir_ / "long.out";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!fs::exists(out / "cases" / "0001" / "run.h5") &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // case 1 is in its run loop
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 130) << read(dir_ / "first.txt");
  const Csv stopped = read_csv(out / "summary.csv");
  ASSERT_EQ(stopped.rows.size(), 3u) << "the summary is written on interruption too";
  EXPECT_EQ(stopped.at(0, "status"), "completed");
  ASSERT_EQ(stopped.at(1, "status"), "interrupted") << read(dir_ / "first.txt");
  EXPECT_TRUE(fs::exists(out / "cases" / "0001" / "checkpoint.h5"));
  EXPECT_EQ(stopped.at(2, "status"), "not_run");
  const std::string first_summary = read(out / "cases" / "0000" / "summary.json");

  ASSERT_EQ(carom("sweep long.toml"), 0) << out_;
  EXPECT_NE(out_.find("1 to resume"), std::string::npos) << out_;
  EXPECT_EQ(read(out / "cases" / "0000" / "summary.json"), first_summary)
      << "a finished case was rerun";
  EXPECT_EQ(case_result(out / "cases" / "0000")["attempts"], 1);
  EXPECT_EQ(case_result(out / "cases" / "0001")["attempts"], 2);
  const auto resumed = case_metrics(out / "cases" / "0001");
  EXPECT_GT(resumed.at("start_time"), 0.0) << "case 1 was rerun from t = 0 instead of resumed";

  ASSERT_EQ(carom("sweep long.toml --out whole --quiet"), 0) << out_;
  const Csv a = read_csv(out / "summary.csv"), b = read_csv(dir_ / "whole" / "summary.csv");
  ASSERT_EQ(a.header, b.header);
  ASSERT_EQ(a.rows.size(), 3u);
  ASSERT_EQ(b.rows.size(), 3u);
  for (std::size_t c = 0; c < a.header.size(); ++c) {
    const std::string& name = a.header[c];
    if (kWallClock.count(name) || name == "attempts") continue;
    for (const std::size_t r : {0, 2})
      EXPECT_EQ(a.rows[r][c], b.rows[r][c]) << "case " << r << ": " << name;
    const bool whole_run = name == "end_time" || name == "particles" || name == "events_total" ||
                           name == "collisions_total" || name.rfind("energy.", 0) == 0 ||
                           name.rfind("analysis.", 0) == 0 ||  // the analysis covers t = 0 to the end
                           name == "status" || name == "seed" || name == "case";
    if (whole_run) {
      EXPECT_EQ(a.rows[1][c], b.rows[1][c]) << "resumed case 1: " << name;
    }
  }
  EXPECT_TRUE(std::any_of(a.header.begin(), a.header.end(), [](const std::string& name) {
    return name.rfind("analysis.collision_frequency.", 0) == 0;
  })) << "the cases' analysis must be gathered";
}

// mpirun -n 2: the four cases are shared between the ranks, each run exactly once (one
// attempt, one log header), and the summary is the local sweep's. A build without MPI must
// refuse to run as several ranks instead.
TEST_F(Sweep, MpiRanksShareTheCasesAndAgreeWithALocalSweep) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "mpirun is not installed";
  file("grid.toml", kGrid);
  const std::string mpirun = "mpirun --allow-run-as-root --oversubscribe -n 2";
#ifndef CAROM_TEST_HAVE_MPI
  ASSERT_EQ(carom("sweep grid.toml", mpirun), 2) << out_;
  EXPECT_NE(out_.find("built without MPI"), std::string::npos) << out_;
  GTEST_SKIP() << "this carom has no MPI: checked that it refuses to run under mpirun";
#endif
  ASSERT_EQ(carom("sweep grid.toml --out local --jobs 2 --quiet"), 0) << out_;
  ASSERT_EQ(carom("sweep grid.toml --out mpi", mpirun), 0) << out_;
  std::set<int> ranks;
  for (std::size_t k = 0; k < 4; ++k) {
    const fs::path case_dir = dir_ / "mpi" / "cases" / ("000" + std::to_string(k));
    const Json result = case_result(case_dir);
    EXPECT_EQ(result["attempts"], 1) << "case " << k;
    ranks.insert(result["rank"].get<int>());
    const std::string log = read(case_dir / "log.txt");
    EXPECT_EQ(log.find("# carom sweep: attempt"), log.rfind("# carom sweep: attempt"))
        << "case " << k << " ran twice";
  }
  EXPECT_EQ(ranks, (std::set<int>{0, 1})) << "both ranks should have run cases";
  expect_same_results(read_csv(dir_ / "local" / "summary.csv"),
                      read_csv(dir_ / "mpi" / "summary.csv"));
}

// Mistakes in a sweep file: exit 2, a message with the file, the line and the key, nothing
// run or written.
TEST_F(Sweep, SweepFileErrorsNameFileLineAndKey) {
  const std::string head = "[sweep]\nscene = \"" + kGas + "\"\n";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {head + "sceen = \"x.toml\"\n", {"bad.toml:3", "unknown key 'sweep.sceen'"}},
      {head + "[[sweep.vary]]\nkey = \"time.end\"\nvalues = []\n",
       {"bad.toml:5", "sweep.vary[0].values", "is empty"}},
      {head + "[[sweep.vary]]\nkey = \"time.end\"\nvalue = [1.0]\n",
       {"bad.toml:5", "did you mean 'sweep.vary[0].values'"}},
      {head + "seeds = [1, -2]\n", {"bad.toml:3", "sweep.seeds", "integer >= 0"}},
      {head + "seeds = [3, 3]\n", {"bad.toml:3", "sweep.seeds", "twice"}},
      {head + "seeds = 3\n", {"bad.toml:3", "sweep.seeds", "not an array"}},
      {"[sweep]\nscene = \"missing.toml\"\n", {"bad.toml:2", "sweep.scene", "names no file"}},
      {"[sweeps]\nscene = \"x\"\n", {"bad.toml:1", "unknown key 'sweeps'"}},
      {head + "[[sweep.vary]]\nkey = \"initial.seed\"\nvalues = [1, 2]\n",
       {"bad.toml:4", "sweep.seeds"}},
      // A value the scene does not allow: found before anything runs, naming the case.
      {head + "[[sweep.vary]]\nkey = \"collisions.default.e\"\nvalues = [0.9, 1.5]\n",
       {"case 1 (collisions.default.e=1.5, seed 1)",
        "collisions.default.e = 1.5 is outside the allowed range [0, 1]"}},
      {head + "set = { \"time.ennd\" = 1.0 }\n",
       {"unknown key 'time.ennd'", "did you mean 'time.end'"}},
  };
  for (const auto& [text, expected] : cases) {
    file("bad.toml", text);
    EXPECT_EQ(carom("sweep bad.toml"), 2) << text << "\n" << out_;
    for (const std::string& piece : expected)
      EXPECT_NE(out_.find(piece), std::string::npos) << text << "\n" << out_;
    EXPECT_FALSE(fs::exists(dir_ / "bad.out")) << "a bad sweep wrote outputs:\n" << text;
  }
  EXPECT_EQ(carom("sweep nowhere.toml"), 2) << out_;
  EXPECT_NE(out_.find("nowhere.toml: cannot open"), std::string::npos) << out_;
  file("ok.toml", kGrid);
  EXPECT_EQ(carom("sweep ok.toml --dry-run"), 0) << out_;
  EXPECT_NE(out_.find("4 cases, all valid"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "ok.out")) << "--dry-run wrote outputs";
}

// A case whose value the scene refuses used to be reported "(set on the command line)"; the
// message now names the sweep file's line where the value is written (vary values and set).
TEST_F(Sweep, CaseErrorsNameTheSweepFileLine) {
  const std::string head = "[sweep]\nscene = \"" + kGas + "\"\n";
  file("bad.toml", head + "[[sweep.vary]]\nkey = \"collisions.default.e\"\n\nvalues = [0.9, 1.5]\n");
  EXPECT_EQ(carom("sweep bad.toml"), 2) << out_;
  EXPECT_NE(out_.find("bad.toml:6 (for "), std::string::npos) << out_;
  EXPECT_NE(out_.find("collisions.default.e = 1.5 is outside the allowed range [0, 1]"), std::string::npos) << out_;
  EXPECT_EQ(out_.find("command line"), std::string::npos) << out_;
  file("bad.toml", head + "\nset = { \"time.end\" = -2.0 }\n");
  EXPECT_EQ(carom("sweep bad.toml"), 2) << out_;
  EXPECT_NE(out_.find("bad.toml:4 (for "), std::string::npos) << out_;
  EXPECT_NE(out_.find("time.end = -2"), std::string::npos) << out_;
  EXPECT_EQ(out_.find("command line"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "bad.out")) << "a bad sweep wrote outputs";
}

// An OUT made by one sweep file is refused to a changed one (different overrides for case 0),
// naming the case: results of two sweeps are never mixed.
TEST_F(Sweep, ChangedSweepFileIsRefused) {
  const std::string head = "[sweep]\nscene = \"" + kGas + "\"\nout = \"s.out\"\n";
  file("s.toml", head + "set = { \"time.end\" = 0.5 }\n");
  ASSERT_EQ(carom("sweep s.toml --quiet"), 0) << out_;
  file("s.toml", head + "set = { \"time.end\" = 0.6 }\n");
  EXPECT_EQ(carom("sweep s.toml"), 2) << out_;
  EXPECT_NE(out_.find("case 0"), std::string::npos) << out_;
  EXPECT_NE(out_.find("was run with --set time.end=0.5"), std::string::npos) << out_;
  file("s.toml", head + "set = { \"time.end\" = 0.5 }\n# a comment does not change the scene\n");
  EXPECT_EQ(carom("sweep s.toml"), 0) << out_;
}
