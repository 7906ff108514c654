// `carom chart` run as a user runs it, on a small elastic gas (330 spheres, phi = 0.1) whose
// collision frequency kinetic theory knows: the event-driven reference, Monte Carlo with the
// Enskog contact value, Monte Carlo without it (which must come out low by 1 - 1/g0 = 23 %,
// Enskog's contact value at phi = 0.1 being g0 = 1.30316, tests/VALIDATION.md), and soft spheres.
// Every number of the chart's table is recomputed here from the cases' own summary.json and
// result.json; the report must name the cheapest variant within the tolerance found the same
// way. Then: a second run changes nothing, the figures are drawn, and mistakes are reported.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"

extern char** environ;

namespace {

using namespace carom_cli_test;
using Json = nlohmann::json;

const std::string kGas =
    "[domain]\nmin = [0, 0, 0]\nmax = [12.0, 12.0, 12.0]\nperiodic = [\"x\", \"y\", \"z\"]\n"
    "gravity = [0.0, 0.0, 0.0]\n"
    "[[species]]\nname = \"a\"\ndiameter = 1.0\ndensity = 1.909859317102744\n"
    "fill = { volume_fraction = 0.1 }\n"
    "[collisions]\ndefault = { e = 1.0, mu = 0.0, beta0 = -1.0 }\n"
    "[initial]\ntemperature = 1.0\n"
    "[time]\nend = 20.0\n"
    "[output]\nsnapshot_every = 20.0\nsample_every = 1.0\ncheckpoint_every = 20.0\n";

const std::string kChart = R"([chart]
scene = "gas.toml"
seeds = [1, 2, 3]
reference = "event-driven"

[[chart.observable]]
key = "analysis.collision_frequency.a-a"
tolerance = 0.05

[[chart.observable]]
key = "mean_temperature"
tolerance = 0.01
error = "absolute"

[[chart.variant]]
name = "event-driven"
set = { "method.kind" = "event_driven" }

[[chart.variant]]
name = "mc enskog"
set = { "method.kind" = "monte_carlo", "monte_carlo.contact_value" = "enskog" }

[[chart.variant]]
name = "mc ideal"
set = { "method.kind" = "monte_carlo", "monte_carlo.contact_value" = "none" }

[[chart.variant]]
name = "soft"
set = { "method.kind" = "soft_sphere", "soft_sphere.contact_model" = "linear", "soft_sphere.contact_time" = 0.02 }
)";

/// A CSV file as rows of cells (no quoted cells in these tables but the names, which have
/// no commas).
std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read(path));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells{""};
    for (const char c : line) {
      if (c == ',')
        cells.emplace_back();
      else
        cells.back() += c;
    }
    rows.push_back(cells);
  }
  return rows;
}

double number(const std::string& cell) {
  return cell.empty() ? std::numeric_limits<double>::quiet_NaN() : std::stod(cell);
}

struct Stats {
  double mean, se;
};
Stats stats(const std::vector<double>& x) {
  double sum = 0;
  for (const double v : x) sum += v;
  const double mean = sum / static_cast<double>(x.size());
  double squares = 0;
  for (const double v : x) squares += (v - mean) * (v - mean);
  return {mean,
          std::sqrt(squares / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()))};
}

class Chart : public Cli {};

TEST_F(Chart, EndToEndOnAGasKineticTheoryKnows) {
  scene("gas.toml", kGas);
  scene("chart.toml", kChart);
  ASSERT_EQ(carom("chart chart.toml --jobs 2"), 0) << out_;
  const fs::path out = dir_ / "chart.out";
  for (const char* file : {"chart.csv", "chart_cases.csv", "chart.h5", "report.md", "chart.toml",
                           "summary.csv", "summary.h5"})
    EXPECT_TRUE(fs::exists(out / file)) << file;

  // The per-seed numbers, straight from the cases' files.
  const std::vector<std::string> names = {"event-driven", "mc enskog", "mc ideal", "soft"};
  const std::vector<std::string> keys = {"analysis.collision_frequency.a-a", "mean_temperature"};
  std::vector<std::vector<double>> cost(4);
  std::vector<std::vector<std::vector<double>>> values(4, std::vector<std::vector<double>>(2));
  for (int k = 0; k < 12; ++k) {
    char name[8];
    std::snprintf(name, sizeof(name), "%04d", k);
    const fs::path dir = out / "cases" / name;
    const Json summary = Json::parse(read(dir / "summary.json"));
    const Json result = Json::parse(read(dir / "result.json"));
    ASSERT_EQ(summary["status"], "completed") << k;
    const double cpu = result["cpu_seconds"].get<double>();
    // CPU time present and positive, and no more than the wall time the sweep saw (one thread).
    EXPECT_GT(cpu, 0.0) << k;
    EXPECT_LE(cpu, result["elapsed_seconds"].get<double>() * 1.05 + 0.02) << k;
    EXPECT_EQ(summary["end_time"].get<double>(), 20.0);
    cost[k / 3].push_back(cpu / 20.0);
    values[k / 3][0].push_back(summary["analysis"]["collision_frequency"]["a-a"].get<double>());
    values[k / 3][1].push_back(summary["mean_temperature"].get<double>());
  }

  // chart.csv: every variant, every number recomputed from the per-seed ones.
  const auto rows = read_csv(out / "chart.csv");
  ASSERT_EQ(rows.size(), 5u);
  const std::vector<std::string>& header = rows[0];
  auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return static_cast<std::size_t>(it - header.begin());
  };
  const Stats ref_rate = stats(values[0][0]), ref_temperature = stats(values[0][1]);
  std::vector<double> rate_error(4), rate_cost(4);
  for (std::size_t v = 0; v < 4; ++v) {
    const std::vector<std::string>& row = rows[v + 1];
    EXPECT_EQ(row[column("variant")], names[v]);
    EXPECT_EQ(row[column("reference")], v == 0 ? "true" : "false");
    EXPECT_EQ(row[column("n_completed")], "3");
    const Stats c = stats(cost[v]);
    EXPECT_NEAR(number(row[column("cost")]), c.mean, 1e-12 * c.mean);
    EXPECT_NEAR(number(row[column("cost_stderr")]), c.se, 1e-9 * c.mean);
    rate_cost[v] = c.mean;
    // Relative error of the rate, and absolute error of the temperature.
    const Stats r = stats(values[v][0]);
    const std::string rk = keys[0];
    EXPECT_NEAR(number(row[column(rk + ":mean")]), r.mean, 1e-12 * r.mean);
    EXPECT_NEAR(number(row[column(rk + ":stderr")]), r.se, 1e-9 * r.mean);
    const double error = v == 0 ? 0.0 : r.mean / ref_rate.mean - 1;
    const double ratio = r.mean / ref_rate.mean;
    const double u =
        v == 0 ? ref_rate.se / ref_rate.mean
               : std::sqrt(r.se * r.se + ratio * ratio * ref_rate.se * ref_rate.se) / ref_rate.mean;
    EXPECT_NEAR(number(row[column(rk + ":error")]), error, 1e-12);
    EXPECT_NEAR(number(row[column(rk + ":uncertainty")]), u, 1e-12);
    EXPECT_EQ(row[column(rk + ":within_noise")], std::abs(error) < u ? "true" : "false");
    EXPECT_EQ(row[column(rk + ":within_tolerance")], std::abs(error) <= 0.05 ? "true" : "false");
    rate_error[v] = error;
    const Stats t = stats(values[v][1]);
    const std::string tk = keys[1];
    EXPECT_NEAR(number(row[column(tk + ":error")]), v == 0 ? 0.0 : t.mean - ref_temperature.mean,
                1e-12);
    EXPECT_NEAR(number(row[column(tk + ":uncertainty")]),
                v == 0 ? t.se : std::sqrt(t.se * t.se + ref_temperature.se * ref_temperature.se),
                1e-12);
  }

  // Physics: the reference is Enskog's gas (330 spheres over 20 s, about 6000 collisions a run:
  // statistical deviations of 1 to 2 % per seed, finite-size ones below that; 5 % is more than
  // four of the mean's standard errors). Monte Carlo without the contact value misses the factor
  // g0, so its error is 1/g0 - 1 = -0.2326, within three of its uncertainties (which hold the
  // random walk of its temperature, a few cells of partners) plus 2 % for the partner statistics
  // drawn per cell.
  const double enskog = 4 * (0.1 * 6 / M_PI) * 1.30316 * std::sqrt(M_PI);
  EXPECT_NEAR(ref_rate.mean / enskog, 1.0, 0.05) << ref_rate.mean << " vs " << enskog;
  const double u_ideal = number(rows[3][column(keys[0] + ":uncertainty")]);
  EXPECT_NEAR(rate_error[2], 1 / 1.30316 - 1, 3 * u_ideal + 0.02);
  EXPECT_EQ(rows[3][column(keys[0] + ":within_tolerance")], "false");

  // The report names the cheapest variant other than the reference within 5 %, found here
  // from the per-seed numbers.
  std::optional<std::size_t> cheapest;
  for (std::size_t v = 1; v < 4; ++v)
    if (std::abs(rate_error[v]) <= 0.05 && (!cheapest || rate_cost[v] < rate_cost[*cheapest]))
      cheapest = v;
  const std::string report = read(out / "report.md");
  ASSERT_TRUE(cheapest.has_value()) << report;
  EXPECT_NE(report.find("Cheapest within the tolerance: **" + names[*cheapest] + "**"),
            std::string::npos)
      << report;
  EXPECT_NE(out_.find(keys[0] + ": cheapest within 0.05 (relative): " + names[*cheapest]),
            std::string::npos)
      << out_;

  // A second run finds every case done: nothing runs, the tables are the same.
  const std::string table = read(out / "chart.csv");
  ASSERT_EQ(carom("chart chart.toml"), 0) << out_;
  EXPECT_NE(out_.find("12 already done, 0 to run"), std::string::npos) << out_;
  EXPECT_EQ(read(out / "chart.csv"), table);

  // The figures, when Python with h5py and matplotlib is there (the Debian packages).
  if (std::system("/usr/bin/python3 -c 'import h5py, matplotlib' > /dev/null 2>&1") == 0) {
    const std::string command = "/usr/bin/python3 " + std::string(CAROM_PLOTS_DIR) +
                                "/chart_plot.py '" + out.string() + "' > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_GT(fs::file_size(out / "pareto_analysis.collision_frequency.a-a.png"), 10000u);
    EXPECT_GT(fs::file_size(out / "pareto_mean_temperature.png"), 10000u);
  }
}

TEST_F(Chart, MistakesInTheChartFileRunNothing) {
  scene("gas.toml", kGas);
  std::string bad = kChart;
  bad.replace(bad.find("reference = \"event-driven\""), 26, "reference = \"ed\"");
  scene("bad.toml", bad);
  EXPECT_EQ(carom("chart bad.toml"), 2) << out_;
  EXPECT_NE(
      out_.find("bad.toml:4: chart.reference = \"ed\" names no variant (allowed: \"event-driven\""),
      std::string::npos)
      << out_;
  EXPECT_FALSE(fs::exists(dir_ / "bad.out"));

  // A variant whose change the scene refuses: named with the chart file's line, nothing run.
  std::string wrong = kChart;
  wrong.replace(wrong.find("\"monte_carlo.contact_value\" = \"none\""), 36,
                "\"monte_carlo.time_step\" = -1.0");
  scene("wrong.toml", wrong);
  EXPECT_EQ(carom("chart wrong.toml"), 2) << out_;
  EXPECT_NE(
      out_.find(
          "wrong.toml:25 (for gas.toml): monte_carlo.time_step = -1 is outside the allowed range"),
      std::string::npos)
      << out_;
  EXPECT_NE(out_.find("monte_carlo.time_step"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "wrong.out" / "cases" / "0000" / "summary.json"));
}

TEST_F(Chart, AnObservableNoSummaryHoldsIsNamedAfterTheRuns) {
  scene("gas.toml", kGas + "");
  const std::string chart = R"([chart]
scene = "gas.toml"
seeds = [1, 2]
reference = "ed"
set = { "time.end" = 2.0 }

[[chart.observable]]
key = "collision_rate_per_particle.a-b"
tolerance = 0.05

[[chart.variant]]
name = "ed"

[[chart.variant]]
name = "mc"
set = { "method.kind" = "monte_carlo" }
)";
  scene("typo.toml", chart);
  EXPECT_EQ(carom("chart typo.toml --quiet"), 2) << out_;
  EXPECT_NE(
      out_.find(
          "typo.toml:8: chart.observable[0].key = \"collision_rate_per_particle.a-b\" is not a "
          "number in any completed case's summary.json; did you mean "
          "\"collision_rate_per_particle.a-a\"?"),
      std::string::npos)
      << out_;
  // The cases ran and the tables are written: fixing the key needs no new run.
  EXPECT_TRUE(fs::exists(dir_ / "typo.out" / "chart.csv"));
  std::string fixed = chart;
  fixed.replace(fixed.find("a-b"), 3, "a-a");
  scene("typo.toml", fixed);
  EXPECT_EQ(carom("chart typo.toml"), 0) << out_;
  EXPECT_NE(out_.find("4 already done, 0 to run"), std::string::npos) << out_;
}

// SIGINT to a chart while a soft-sphere case runs: exit 130, the case checkpointed. The same
// command continues it (the sweep's resume); its cost is the CPU time of both attempts over the
// whole simulated time, and its observable (the analysis covers t = 0 to the end) is bit for
// bit that of a chart that was never interrupted.
TEST_F(Chart, AnInterruptedChartResumesAndCountsEveryAttempt) {
  scene("gas.toml", kGas);
  scene("long.toml", R"([chart]
scene = "gas.toml"
seeds = [1, 2]
reference = "ed"
set = { "time.end" = 60.0, "output.checkpoint_every" = 20.0 }

[[chart.observable]]
key = "analysis.collision_frequency.a-a"
tolerance = 0.05

[[chart.variant]]
name = "ed"

[[chart.variant]]
name = "soft"
set = { "method.kind" = "soft_sphere", "soft_sphere.contact_model" = "linear", "soft_sphere.contact_time" = 0.02 }
)");
  std::vector<std::string> args{kCarom, "chart", "long.toml"};
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
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, kCarom.c_str(), &actions, nullptr, argv.data(), environ), 0);
  fs::current_path(cwd);
  posix_spawn_file_actions_destroy(&actions);
  const fs::path out = dir_ / "long.out";
  const fs::path soft = out / "cases" / "0002";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(soft / "run.h5") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // in its run loop (about 1 s long)
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 130) << read(dir_ / "first.txt");
  const Json stopped = Json::parse(read(soft / "result.json"));
  ASSERT_EQ(stopped["status"], "interrupted") << read(dir_ / "first.txt");
  const double first_cpu = stopped["cpu_seconds"].get<double>();
  EXPECT_GT(first_cpu, 0.0);
  EXPECT_TRUE(fs::exists(out / "chart.csv")) << "the tables are written on interruption too";

  ASSERT_EQ(carom("chart long.toml"), 0) << out_;
  EXPECT_NE(out_.find("1 to resume"), std::string::npos) << out_;
  const Json done = Json::parse(read(soft / "result.json"));
  EXPECT_EQ(done["attempts"], 2);
  const double total_cpu = done["cpu_seconds"].get<double>();
  EXPECT_GT(total_cpu, first_cpu);
  const auto rows = read_csv(out / "chart_cases.csv");
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0][4], "cpu_seconds");
  EXPECT_EQ(rows[0][6], "cost");
  EXPECT_NEAR(number(rows[3][4]), total_cpu, 1e-12);
  EXPECT_NEAR(number(rows[3][6]), total_cpu / 60.0, 1e-12);

  ASSERT_EQ(carom("chart long.toml --out whole --quiet"), 0) << out_;
  const auto whole = read_csv(dir_ / "whole" / "chart_cases.csv");
  ASSERT_EQ(whole.size(), 5u);
  for (std::size_t r = 1; r < 5; ++r) EXPECT_EQ(rows[r][7], whole[r][7]) << "case " << r - 1;
}

// mpirun -n 2: the ranks share the cases (the sweep's own MPI test checks how), and only the
// first process writes the chart's tables and prints its conclusions, once MPI is down: the
// observables are bit for bit those of a local chart.
TEST_F(Chart, UnderMpirunTheFirstRankWritesTheSameTables) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun";
#ifndef CAROM_TEST_HAVE_MPI
  GTEST_SKIP() << "this carom has no MPI";
#endif
  scene("gas.toml", kGas);
  scene("small.toml", R"([chart]
scene = "gas.toml"
seeds = [1, 2]
reference = "ed"
set = { "time.end" = 2.0 }

[[chart.observable]]
key = "analysis.collision_frequency.a-a"
tolerance = 0.05

[[chart.variant]]
name = "ed"

[[chart.variant]]
name = "mc"
set = { "method.kind" = "monte_carlo" }
)");
  ASSERT_EQ(carom("chart small.toml --out local --jobs 2 --quiet"), 0) << out_;
  const std::string command =
      "cd '" + dir_.string() +
      "' && timeout -k 5 60 mpirun --allow-run-as-root --oversubscribe -n 2 '" + kCarom +
      "' chart small.toml --out mpi > mpi.txt 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read(dir_ / "mpi.txt");
  const std::string printed = read(dir_ / "mpi.txt");
  const std::string conclusion = "carom chart: analysis.collision_frequency.a-a:";
  EXPECT_NE(printed.find(conclusion), std::string::npos) << printed;
  EXPECT_EQ(printed.find(conclusion), printed.rfind(conclusion)) << "printed by two ranks:\n"
                                                                 << printed;
  const auto local = read_csv(dir_ / "local" / "chart_cases.csv");
  const auto mpi = read_csv(dir_ / "mpi" / "chart_cases.csv");
  ASSERT_EQ(local.size(), 5u);
  ASSERT_EQ(mpi.size(), 5u);
  for (std::size_t r = 0; r < 5; ++r)
    for (const std::size_t c : {0, 1, 2, 3, 5, 7})
      EXPECT_EQ(local[r][c], mpi[r][c]) << r << "," << c;
  EXPECT_GT(number(mpi[1][4]), 0.0) << "CPU seconds of a case run by a rank's pool";
}

}  // namespace
