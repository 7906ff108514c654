// summary.json's units (scenarios/run/summary_units.hpp): every key that runs of six kinds write
// matches one row of the table, with a value of the row's kind (a string for "text", true or
// false for "bool", else numbers or null); the file's "units" object is the table; every row is
// met by some run (no stale rows) and is explained on scenarios/run/SUMMARY.md. A new key
// without a row fails here.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "scenarios/run/summary_units.hpp"

namespace carom_cli_test {
namespace {

using Json = nlohmann::ordered_json;

/// The page that documents the table, beside the header.
const fs::path kPage = fs::path(CAROM_SCENES_DIR) / ".." / "run" / "SUMMARY.md";

/// Walls on four sides, a tagged body and profiles across two sections: wall_collisions,
/// wall_force, analysis.tagged_bodies and analysis.profiles.
const std::string kWalledGas = R"(
[domain]
min = [0, 0, 0]
max = [8.0, 8.0, 8.0]
periodic = ["y"]
[[species]]
name = "a"
diameter = 1.0
density = 1.909859317102744
fill = { volume_fraction = 0.1 }
[[particles]]
species = "a"
position = [4.0, 4.0, 4.0]
velocity = [0.0, 0.0, 3.0]
tagged = true
[collisions]
default = { e = 0.9, mu = 0.1, beta0 = 0.3 }
[initial]
seed = 2
temperature = 1.0
[time]
end = 2.0
[output]
snapshot_every = 0
sample_every = 0.1
[analysis.profiles]
heights = [2.0, 6.0]
thickness = 2.0
axis = "x"
bins = 2
start = 0.5
)";

/// The leaves of a summary under `path`: objects by key, arrays that hold an object by index;
/// any other array (a vector, a list per bin or per species) is one leaf.
void leaves(const Json& node, const std::string& path, std::vector<std::pair<std::string, Json>>& out) {
  const auto below = [&](const std::string& key) { return path.empty() ? key : path + "." + key; };
  if (node.is_object()) {
    for (const auto& [key, value] : node.items()) leaves(value, below(key), out);
    return;
  }
  if (node.is_array()) {
    bool objects = false;
    for (const Json& element : node) objects |= element.is_object();
    if (objects) {
      for (std::size_t k = 0; k < node.size(); ++k) leaves(node[k], below(std::to_string(k)), out);
      return;
    }
  }
  out.emplace_back(path, node);
}

/// True when `value` (a leaf) is of the kind `unit` announces.
bool kind_agrees(std::string_view unit, const Json& value) {
  if (unit == "text") return value.is_string();
  if (unit == "bool") return value.is_boolean();
  if (value.is_array()) {
    for (const Json& element : value)
      if (!kind_agrees(unit, element)) return false;
    return true;
  }
  return value.is_number() || value.is_null();
}

class SummaryUnits : public Cli {
 protected:
  /// Runs `carom run ARGS --out NAME --quiet` and checks its summary.json against the table;
  /// adds the patterns its keys matched to `met_`.
  void check_run(const std::string& args, const std::string& name) {
    ASSERT_EQ(carom("run " + args + " --out " + name + " --quiet"), 0) << out_;
    const Json summary = Json::parse(read(dir_ / name / "summary.json"));
    ASSERT_TRUE(summary.contains("units")) << name;
    EXPECT_EQ(summary["units"], Json::parse(carom::summary_units_json())) << name;
    ASSERT_EQ(summary["units"].size(), std::size(carom::kSummaryKeys)) << name;
    std::vector<std::pair<std::string, Json>> found;
    for (const auto& [key, value] : summary.items())
      if (key != "units") leaves(value, key, found);
    for (const auto& [path, value] : found) {
      std::vector<const carom::SummaryKey*> rows;
      for (const carom::SummaryKey& row : carom::kSummaryKeys)
        if (carom::summary_pattern_matches(row.pattern, path)) rows.push_back(&row);
      if (rows.empty() && value.is_null()) {
        // An object that does not apply here (enskog_rate_per_particle: null): rows below it.
        bool below = false;
        for (const carom::SummaryKey& row : carom::kSummaryKeys)
          below |= row.pattern.substr(0, path.size() + 1) == path + ".";
        EXPECT_TRUE(below) << name << ": " << path << " is null and no row lies below it";
        continue;
      }
      ASSERT_EQ(rows.size(), 1u) << name << ": " << path << " matches " << rows.size()
                                 << " rows of summary_units.hpp (a new key needs its row)";
      EXPECT_TRUE(kind_agrees(rows[0]->unit, value))
          << name << ": " << path << " = " << value.dump() << " but its unit is " << rows[0]->unit;
      met_.insert(std::string(rows[0]->pattern));
    }
  }

  std::set<std::string> met_;
};

TEST(SummaryUnitsTable, RowsAreUniqueWithKnownUnitsAndEachIsOnThePage) {
  const std::set<std::string> words{"1", "count", "text", "bool"};
  const std::string page = read(kPage);
  ASSERT_FALSE(page.empty()) << kPage;
  std::set<std::string> patterns;
  for (const carom::SummaryKey& row : carom::kSummaryKeys) {
    const std::string pattern(row.pattern), unit(row.unit);
    EXPECT_TRUE(patterns.insert(pattern).second) << pattern << " twice";
    EXPECT_FALSE(row.meaning.empty()) << pattern;
    // Nothing JSON would have to escape, so summary_units_json may write the text as it is.
    EXPECT_EQ(pattern.find_first_of("\"\\"), std::string::npos) << pattern;
    // A word of the vocabulary or an SI unit such as m^2/s^2, kg/s, 1/s.
    EXPECT_TRUE(words.count(unit) || unit.find_first_not_of("kgmsJNPaWrd^/0123456789") == std::string::npos)
        << pattern << ": " << unit;
    EXPECT_NE(page.find("`" + pattern + "`"), std::string::npos) << pattern << " is not on " << kPage;
  }
  EXPECT_TRUE(carom::summary_pattern_matches("collision_rate_per_particle.*", "collision_rate_per_particle.a-b"));
  EXPECT_FALSE(carom::summary_pattern_matches("collision_rate_per_particle.*", "collision_rate_per_particle.a.b"));
  EXPECT_FALSE(carom::summary_pattern_matches("collision_rate_per_particle.*", "collision_rate_per_particle."));
  EXPECT_TRUE(carom::summary_pattern_matches("flow.inflows.*.name", "flow.inflows.12.name"));
  EXPECT_EQ(carom::summary_key_for("analysis.granular_temperature.glass")->unit, "m^2/s^2");
  EXPECT_EQ(carom::summary_key_for("mean_temperature")->unit, "J");
  EXPECT_EQ(carom::summary_key_for("nothing.here"), nullptr);
}

// Six runs: a periodic gas of two species (Enskog, segregation), a gas-fluidized bed with
// [analysis] mixing and bed measures, a walled gas with a tagged body and profiles, a fed duct with soft spheres
// (flow, soft-sphere quantities), a gas with the Monte Carlo method, a tube with plugs. About
// 3 s together.
TEST_F(SummaryUnits, EveryKeyOfSummaryJsonHasItsUnit) {
  check_run(scene("gas.toml", kSmallGas), "gas");
  check_run(kScenes + "/small_bed.toml --set time.end=0.1 --set 'analysis.bed.probes=[[0.004, 0.002, 0.002]]'"
                      " --set 'analysis.bed.probe_heights=[0.01]'",
            "bed");
  check_run(scene("walled.toml", kWalledGas), "walled");
  check_run(kScenes + "/duct_flow.toml --set method.kind='\"soft_sphere\"' --set time.end=0.1", "duct");
  check_run(kScenes + "/mc_gas.toml --set method.kind='\"monte_carlo\"' --set time.end=0.1", "mc");
  check_run(kScenes + "/column_1d.toml --set analysis.plugs.threshold=0.3 --set initial.settle_time=0.01"
                      " --set time.end=0.03",
            "tube");
  if (HasFatalFailure()) return;
  // Every row is met: a row whose key is no longer written is stale.
  for (const carom::SummaryKey& row : carom::kSummaryKeys)
    EXPECT_TRUE(met_.count(std::string(row.pattern))) << row.pattern << " was written by none of the runs";
}

}  // namespace
}  // namespace carom_cli_test
