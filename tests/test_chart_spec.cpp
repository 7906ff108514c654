// `carom chart`'s file and tables without running anything: every class of mistake in a chart
// file (the message names the file, the line, the key and what is allowed), the sweep a chart
// becomes (each variant's changes, in case order), and the chart's table gathered from a
// constructed sweep table (costs from CPU seconds and simulated time, failed cases left out,
// errors from the per-seed numbers, an observable that no summary holds).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "scenarios/chart/chart_spec.hpp"
#include "scenarios/chart/chart_table.hpp"

namespace carom {
namespace {

namespace fs = std::filesystem;

/// A folder with a scene file (its content is not read by read_chart).
class ChartFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("carom_chart_spec_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "gas.toml") << "# a scene\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Writes chart.toml with `text` and returns its path.
  std::string write(const std::string& text) {
    const fs::path path = dir_ / "chart.toml";
    std::ofstream(path) << text;
    return path.string();
  }
  /// The message read_chart throws for `text` ("" when it throws nothing).
  std::string error_of(const std::string& text) {
    try {
      read_chart(write(text));
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

const std::string kHead = R"([chart]
scene = "gas.toml"
seeds = [1, 2]
reference = "exact"
)";
const std::string kObservable = R"(
[[chart.observable]]
key = "collision_rate_per_particle.a-a"
tolerance = 0.05
)";
const std::string kVariants = R"(
[[chart.variant]]
name = "exact"
set = { "method.kind" = "event_driven" }

[[chart.variant]]
name = "soft"
set = { "method.kind" = "soft_sphere", "soft_sphere.time_step" = 1e-3 }
)";

TEST_F(ChartFile, AGoodFileReads) {
  const ChartSpec spec =
      read_chart(write(kHead + "set = { \"time.end\" = 2.0 }\n" + kObservable + kVariants));
  EXPECT_EQ(spec.scene, (dir_ / "gas.toml").string());
  EXPECT_EQ(spec.out, "chart.out");
  EXPECT_EQ(spec.seeds, (std::vector<std::uint64_t>{1, 2}));
  ASSERT_EQ(spec.variants.size(), 2u);
  EXPECT_EQ(spec.reference, 0u);
  EXPECT_EQ(spec.variants[1].sets, (std::vector<std::string>{"method.kind=\"soft_sphere\"",
                                                             "soft_sphere.time_step=0.001"}));
  EXPECT_EQ(spec.fixed, (std::vector<std::string>{"time.end=2.0"}));
  ASSERT_EQ(spec.observables.size(), 1u);
  EXPECT_EQ(spec.observables[0].measure, ErrorMeasure::Relative);
  EXPECT_DOUBLE_EQ(spec.observables[0].tolerance, 0.05);

  // The sweep: variant slowest, seed fastest; each case gets the fixed changes, then its
  // variant's, each with the line it was written on.
  const std::vector<SweepCase> cases = chart_sweep(spec).cases();
  ASSERT_EQ(cases.size(), 4u);
  EXPECT_EQ(cases[2].group, 1u);
  EXPECT_EQ(cases[2].seed, 1u);
  EXPECT_EQ(cases[3].seed, 2u);
  EXPECT_EQ(cases[3].overrides,
            (std::vector<std::string>{"time.end=2.0", "method.kind=\"soft_sphere\"",
                                      "soft_sphere.time_step=0.001"}));
  ASSERT_EQ(cases[3].origins.size(), 3u);
  EXPECT_NE(cases[3].origins[2].find("chart.toml:17"), std::string::npos) << cases[3].origins[2];
  EXPECT_EQ(chart_sweep(spec).describe_group(1), "variant=soft");
}

TEST_F(ChartFile, MistakesNameFileLineKeyAndWhatIsAllowed) {
  struct Case {
    std::string text, expected_where, expected_key, expected_allowed;
  };
  const std::string f = "chart.toml";
  const std::vector<Case> cases = {
      {"[sweep]\nscene = \"gas.toml\"\n", f + ":1", "this is a sweep file", "carom sweep"},
      {"[domain]\nmin = [0, 0, 0]\n", f, "no [chart] table", "carom run"},
      {kHead + kObservable + kVariants + "[extra]\nx = 1\n", f + ":17", "unknown key 'extra'",
       "known keys here: chart"},
      {kHead + "seed = 3\n" + kObservable + kVariants, f + ":5", "chart.seed", "chart.seeds"},
      {"[chart]\nscene = \"gas.toml\"\nseeds = [1]\nreference = \"exact\"\n" + kObservable +
           kVariants,
       f + ":3", "chart.seeds = [1]", "at least two"},
      {"[chart]\nscene = \"gas.toml\"\nseeds = [1, 1]\nreference = \"exact\"\n" + kObservable +
           kVariants,
       f + ":3", "chart.seeds", "twice"},
      {"[chart]\nscene = \"nowhere.toml\"\nseeds = [1, 2]\nreference = \"exact\"\n" + kObservable +
           kVariants,
       f + ":2", "chart.scene", "names no scene file"},
      {"[chart]\nscene = \"gas.toml\"\nseeds = [1, 2]\nreference = \"best\"\n" + kObservable +
           kVariants,
       f + ":4", "chart.reference = \"best\"", "\"exact\", \"soft\""},
      {kHead + kVariants, f, "chart.observable", "key ="},
      {kHead + "[[chart.observable]]\nkey = \"pressure.total\"\ntolerance = 0.0\n" + kVariants,
       f + ":7", "chart.observable[0].tolerance = 0", "(0, inf)"},
      {kHead + "[[chart.observable]]\nkey = \"pressure.total\"\n" + kVariants, f,
       "chart.observable[0].tolerance", "a number > 0"},
      {kHead +
           "[[chart.observable]]\nkey = \"pressure.total\"\ntolerance = 1\nerror = \"percent\"\n" +
           kVariants,
       f + ":8", "chart.observable[0].error = \"percent\"", "\"relative\", \"absolute\""},
      {kHead + "[[chart.observable]]\nkey = \"pressure..total\"\ntolerance = 1\n" + kVariants,
       f + ":6", "chart.observable[0].key", "dotted path"},
      {kHead + kObservable + kObservable + kVariants, f + ":11", "chart.observable[1].key",
       "each once"},
      {kHead + kObservable + kVariants + "[[chart.variant]]\nname = \"soft\"\n", f + ":18",
       "chart.variant[2].name = \"soft\"", "unique names"},
      {kHead + kObservable + kVariants + "[[chart.variant]]\nname = \"x\"\nsets = {}\n", f + ":19",
       "chart.variant[2].sets", "chart.variant[2].set"},
      {kHead + kObservable + kVariants +
           "[[chart.variant]]\nname = \"x\"\nset = { \"initial.seed\" = 4 }\n",
       f + ":19", "initial.seed", "chart.seeds"},
      {kHead + "set = { \"method.kind\" = \"monte_carlo\" }\n" + kObservable + kVariants, f + ":",
       "chart.variant[0].set", "either in chart.set or in the variants"},
      {kHead + kObservable + kVariants +
           "[[chart.variant]]\nname = \"again\"\nset = { \"method.kind\" = \"event_driven\" }\n",
       f + ":19", "chart.variant[2].set", "variant \"exact\""},
      {kHead + kObservable + "[[chart.variant]]\nname = \"exact\"\n", f, "[[chart.variant]]",
       "at least two"},
      {kHead + kObservable + kVariants +
           "[[chart.variant]]\nname = \"a|b\"\nset = { \"time.end\" = 1.0 }\n",
       f + ":18", "chart.variant[2].name", "without '|'"},
      {kHead + kObservable + kVariants + "[[chart.variant]]\nname = \"x\"\nset = 3\n", f + ":19",
       "chart.variant[2].set = 3", "scene changes as for --set"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    ASSERT_FALSE(message.empty()) << "accepted:\n" << c.text;
    EXPECT_NE(message.find(c.expected_where), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected_key), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected_allowed), std::string::npos) << message;
  }
}

// ---------------------------------------------------------------------------------------------
// The table from a constructed sweep table.

TEST(ChartTable, CostsErrorsAndFlagsFromPerSeedNumbers) {
  ChartSpec chart;
  chart.file = "c.toml";
  chart.out = "c.out";
  chart.seeds = {1, 2, 3};
  chart.variants = {{"exact", {}, {}, "c.toml:9"},
                    {"cheap", {}, {}, "c.toml:12"},
                    {"rough", {}, {}, "c.toml:15"}};
  chart.reference = 0;
  chart.observables = {{"rate.a", 0.05, ErrorMeasure::Relative, "c.toml:5"},
                       {"rate.typo", 0.05, ErrorMeasure::Relative, "c.toml:7"}};
  SweepTable sweep;
  sweep.metrics = {"end_time", "rate.a", "rate.b"};
  // Per variant and seed: CPU s, simulated s, rate.a, status.
  struct Row {
    std::size_t variant;
    double cpu, end, rate;
    const char* status;
  };
  const std::vector<Row> rows = {
      {0, 40, 10, 10.0, "completed"}, {0, 44, 10, 10.3, "completed"},
      {0, 42, 10, 9.8, "completed"},  {1, 4, 10, 10.2, "completed"},
      {1, 6, 10, 10.4, "completed"},  {1, 99, 10, 0.0, "failed"},
      {2, 1, 10, 8.0, "completed"},   {2, 1, 10, 8.2, "completed"},
      {2, 1.2, 10, 8.1, "completed"},
  };
  for (std::size_t k = 0; k < rows.size(); ++k) {
    CaseRow row;
    row.c.index = k;
    row.c.group = rows[k].variant;
    row.c.seed = chart.seeds[k % 3];
    row.result.status = rows[k].status;
    row.result.cpu_seconds = rows[k].cpu;
    row.metrics = {rows[k].end, rows[k].rate, 1.0};
    sweep.cases.push_back(row);
  }
  const ChartTable table = chart_table(chart, sweep);
  ASSERT_EQ(table.cases.size(), 9u);
  EXPECT_DOUBLE_EQ(table.cases[1].cost, 4.4);
  EXPECT_TRUE(std::isnan(table.cases[5].cost));  // failed: no cost
  // Reference: costs 4, 4.4, 4.2; rates 10, 10.3, 9.8 -> mean 10.033..., sd 0.25166, se 0.1453.
  const ChartVariantRow& ref = table.variants[0];
  EXPECT_EQ(ref.completed, 3u);
  EXPECT_NEAR(ref.cost.mean, 4.2, 1e-12);
  EXPECT_NEAR(ref.cost.standard_error, 0.2 / std::sqrt(3.0), 1e-12);
  const double ref_mean = (10.0 + 10.3 + 9.8) / 3;
  const double ref_se =
      std::sqrt(((10.0 - ref_mean) * (10.0 - ref_mean) + (10.3 - ref_mean) * (10.3 - ref_mean) +
                 (9.8 - ref_mean) * (9.8 - ref_mean)) /
                2 / 3);
  EXPECT_NEAR(ref.observables[0].statistics.mean, ref_mean, 1e-12);
  EXPECT_NEAR(ref.observables[0].statistics.standard_error, ref_se, 1e-12);
  // "cheap": the failed seed is left out: rates 10.2, 10.4 (mean 10.3, se 0.1), costs 0.4, 0.6.
  const ChartVariantRow& cheap = table.variants[1];
  EXPECT_EQ(cheap.cases, 3u);
  EXPECT_EQ(cheap.completed, 2u);
  EXPECT_NEAR(cheap.cost.mean, 0.5, 1e-12);
  const ChartObservableResult& c = cheap.observables[0];
  EXPECT_NEAR(c.error.error, 10.3 / ref_mean - 1, 1e-12);
  EXPECT_NEAR(
      c.error.uncertainty,
      std::sqrt(0.1 * 0.1 + (10.3 / ref_mean) * (10.3 / ref_mean) * ref_se * ref_se) / ref_mean,
      1e-12);
  EXPECT_TRUE(c.within_tolerance);
  EXPECT_FALSE(c.error.within_noise);  // 2.7 % against an uncertainty of 1.7 %
  // "rough": 19 % low, cheapest: on the front but not within the tolerance.
  const ChartObservableResult& r = table.variants[2].observables[0];
  EXPECT_FALSE(r.within_tolerance);
  EXPECT_TRUE(r.front.on_front);
  EXPECT_TRUE(c.front.on_front);
  EXPECT_TRUE(ref.observables[0].front.on_front);
  EXPECT_EQ(table.cheapest[0], std::optional<std::size_t>(1));
  EXPECT_TRUE(table.problems[0].empty());
  // An observable no summary holds: named with its line, the closest metric suggested.
  EXPECT_NE(table.problems[1].find("c.toml:7"), std::string::npos) << table.problems[1];
  EXPECT_NE(table.problems[1].find("rate.typo"), std::string::npos) << table.problems[1];
  EXPECT_NE(table.problems[1].find("did you mean \"rate.a\""), std::string::npos)
      << table.problems[1];
  EXPECT_EQ(table.cheapest[1], std::nullopt);
}

}  // namespace
}  // namespace carom
