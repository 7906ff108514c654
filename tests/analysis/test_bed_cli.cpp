// The bed measures through the `carom` command line: a run ended and resumed gives the same bed
// series and results bit for bit with each method; the buoyant weight per area of the beads and
// the gas column's part come out as computed by hand; without a gas the pressure fields are
// absent and the report says why; bad [analysis.bed] keys are refused naming file, line, key
// and allowed range.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "core/hdf5.hpp"
#include "scenarios/run/output_estimate.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom_cli_test {
namespace {

// 30 glass beads of 1 mm in an 8 x 4 x 16 mm box, fluidized by a two-way coupled gas (as
// tests/fuzz/resume_gas_bed.toml): about 0.1 s of wall time per 0.05 s simulated.
const std::string kGasBed = R"(
[domain]
min = [0.0, 0.0, 0.0]
max = [0.008, 0.004, 0.016]
periodic = ["y"]
gravity = [0.0, 0.0, -9.81]
[regions.bed]
min = [0.0, 0.0, 0.0]
max = [0.008, 0.004, 0.008]
[[species]]
name = "glass"
diameter = 1.0e-3
density = 2500.0
fill = { region = "bed", count = 30, arrangement = "random" }
[collisions]
default = { e = 0.97, mu = 0.1, beta0 = 0.33 }
walls = { e = 0.97, mu = 0.1, beta0 = 0.33 }
collapse = { model = "tc", contact_time = 1.0e-4 }
[flight]
model = "relax"
[gas]
coupling = "two_way"
density = 1.2
viscosity = 1.8e-5
cells = [2, 1, 4]
time_step = 5.0e-4
drag = "gidaspow_blend"
[gas.boundaries]
z_low = { type = "inlet", velocity = 0.9, ramp_time = 0.1 }
z_high = "outlet"
[initial]
seed = 3
rms_velocity = 0.05
[time]
end = 0.06
[output]
snapshot_every = 0.01
sample_every = 0.001
[analysis.bed]
start = 0.01
probes = [[0.004, 0.002, 0.002], [0.002, 0.002, 0.01]]
probe_heights = [0.004]
map_bins = [4, 8]
)";

/// Every dataset of a group, as doubles, by name.
std::map<std::string, std::vector<double>> datasets(const carom::h5::Group& group) {
  std::map<std::string, std::vector<double>> out;
  for (const std::string& name : group.children()) out[name] = group.read<double>(name);
  return out;
}

/// The bits of each value (NaN, before the first fluid step, is not equal to itself).
std::vector<std::uint64_t> bits(const std::vector<double>& values) {
  std::vector<std::uint64_t> out;
  for (double x : values) out.push_back(std::bit_cast<std::uint64_t>(x));
  return out;
}

/// The "bed" object of a summary.json, as text.
std::string bed_object(const std::string& summary) {
  const std::size_t at = summary.find("\"bed\": ");
  return at == std::string::npos ? "" : summary.substr(at, summary.find('\n', at) - at);
}

/// The bed without its gas: the same beads falling in a closed box.
std::string dry_bed() {
  std::string text = kGasBed;
  text.erase(text.find("[flight]"), text.find("[initial]") - text.find("[flight]"));
  text.erase(text.find("probes = "), text.find("map_bins") - text.find("probes = "));
  return text;
}

TEST_F(Cli, BedMeasuresResumeBitForBitWithEveryMethod) {
  scene("gas.toml", kGasBed);
  scene("dry.toml", dry_bed());
  const std::string soft =
      " --set soft_sphere.contact_model=linear --set soft_sphere.contact_time=1e-4";
  for (const std::string bed : {"dry", "gas"})
    for (const std::string method : {"event_driven", "soft_sphere", "monte_carlo"}) {
      SCOPED_TRACE(bed + " " + method);
      const std::string sets = " --quiet --method " + method + (method == "soft_sphere" ? soft : "");
      const std::string whole = bed + "_" + method + "_whole", part = bed + "_" + method + "_part";
      ASSERT_EQ(carom("run " + bed + ".toml --out " + whole + sets), 0) << out_;
      ASSERT_EQ(carom("run " + bed + ".toml --set time.end=0.025 --out " + part + sets), 0) << out_;
      ASSERT_EQ(carom("resume " + part + " --end 0.06 --quiet"), 0) << out_;
      const auto open = [&](const std::string& run) {
        return carom::h5::File::open((dir_ / run / "run.h5").string(), false);
      };
      const carom::h5::File a_file = open(whole), b_file = open(part);
      std::vector<std::string> names{"time", "bed_height", "bed_map_sums"};
      if (bed == "gas") names.insert(names.end(), {"bed_pressure", "bed_probe_pressure"});
      for (const std::string& name : names) {
        const std::vector<double> a = a_file.open_group("timeseries").read<double>(name);
        const std::vector<double> b = b_file.open_group("timeseries").read<double>(name);
        EXPECT_FALSE(a.empty()) << name;
        EXPECT_EQ(bits(a), bits(b)) << name;
      }
      const auto a = datasets(a_file.open_group("analysis/bed/results"));
      const auto b = datasets(b_file.open_group("analysis/bed/results"));
      ASSERT_EQ(a.size(), b.size());
      for (const auto& [name, values] : a) EXPECT_EQ(bits(values), bits(b.at(name))) << name;
      if (bed == "gas") {  // 51 samples from 0.01 s to 0.06 s: 25 frequencies, for 3 probes
        EXPECT_EQ(a.at("spectrum_amplitude").size(), 3u * 25u);
      }
      const std::string summary = bed_object(read(dir_ / whole / "summary.json"));
      EXPECT_FALSE(summary.empty());
      EXPECT_EQ(summary, bed_object(read(dir_ / part / "summary.json")));
    }
}

TEST_F(Cli, BedWeightAndGasColumnAreTheBeadsAndTheGasOwn) {
  scene("bed.toml", kGasBed);
  ASSERT_EQ(carom("run bed.toml --out r --quiet --set time.end=0.02"), 0) << out_;
  const carom::h5::File file = carom::h5::File::open((dir_ / "r" / "run.h5").string(), false);
  const carom::h5::Group results = file.open_group("analysis/bed/results");
  // W/A = N (rho_p - rho_g) g (pi/6) d^3 / A for 30 beads of 1 mm over the 8 x 4 mm section
  // (the gas grid's open volume over its height: no wall cuts it), to round-off (1e-12).
  const double weight = 30 * (2500.0 - 1.2) * 9.81 * std::numbers::pi / 6 * 1e-9 / (0.008 * 0.004);
  EXPECT_NEAR(results.read<double>("buoyant_weight_per_area")[0] / weight, 1.0, 1e-12);
  EXPECT_NEAR(results.read<double>("gas_column")[0], 1.2 * 9.81 * 0.016, 1e-15);
  EXPECT_EQ(results.open_dataset("gas_column").attribute<std::string>("unit"), "Pa");
  const double drop = results.read<double>("pressure_drop_mean")[0];
  const double inflow = results.read<double>("momentum_inflow_mean")[0];
  EXPECT_NEAR(results.read<double>("bed_pressure_drop")[0], drop - 1.2 * 9.81 * 0.016 + inflow, 1e-12);
  // A bead's top lies at least one diameter above the floor and at most at the lid: so do the
  // share heights (the first two; the surface may be NaN in a bed this dilute).
  const std::vector<double> heights = results.read<double>("height_min");
  const std::vector<double> highest = results.read<double>("height_max");
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_GE(heights[k], 1e-3 * (1 - 1e-12));
    EXPECT_LE(highest[k], 0.016);
  }
  EXPECT_NE(read(dir_ / "r" / "report.md").find("## Bed"), std::string::npos);
}

TEST_F(Cli, BedWithoutAGasHasNoPressureAndSaysWhy) {
  scene("dry.toml", dry_bed());
  ASSERT_EQ(carom("run dry.toml --out r --quiet --set time.end=0.01"), 0) << out_;
  const std::string bed = bed_object(read(dir_ / "r" / "summary.json"));
  EXPECT_NE(bed.find("\"heights\""), std::string::npos) << bed;
  EXPECT_EQ(bed.find("\"pressure\""), std::string::npos) << bed;
  EXPECT_EQ(bed.find("\"probes\""), std::string::npos) << bed;
  EXPECT_NE(read(dir_ / "r" / "report.md").find("No gas in this scene"), std::string::npos);
  const carom::h5::File file = carom::h5::File::open((dir_ / "r" / "run.h5").string(), false);
  EXPECT_FALSE(file.open_group("timeseries").contains("bed_pressure"));
}

// A run whose file is mostly its bed maps (40 x 80 bins, 102 kB a sample): the output estimate
// that refuses runs too large to write counts them, within the factor 1.25 it keeps for the rest.
TEST_F(Cli, BedMapsAreInTheOutputEstimate) {
  scene("dry.toml", dry_bed());
  const std::vector<std::string> overrides{"analysis.bed.map_bins=[40, 80]"};
  ASSERT_EQ(carom("run dry.toml --out r --quiet --set 'analysis.bed.map_bins=[40, 80]'"), 0) << out_;
  const std::size_t particles = nlohmann::json::parse(read(dir_ / "r" / "summary.json"))["particles"];
  const carom::OutputEstimate e =
      carom::estimate_output(carom::load_scene((dir_ / "dry.toml").string(), overrides), particles);
  double written = 0;
  for (const char* name : {"run.h5", "run.xmf", "checkpoint.h5"}) written += double(fs::file_size(dir_ / "r" / name));
  EXPECT_GT(written, 5e6);  // 61 samples of 102 kB: the maps are most of it
  EXPECT_GT(e.bytes, written / 1.25) << "estimate " << e.bytes << " bytes, written " << written;
  EXPECT_LT(e.bytes, written * 1.25) << "estimate " << e.bytes << " bytes, written " << written;
}

TEST_F(Cli, BedKeysOutOfRangeNameFileLineKeyAndRange) {
  // Each bad key is the only one of a fresh [analysis.bed] section, on the line after its header.
  const std::string base = kGasBed.substr(0, kGasBed.find("[analysis.bed]\n") + 15);
  const std::string line = "bad.toml:" + std::to_string(std::count(base.begin(), base.end(), '\n') + 1) + ":";
  struct Case {
    std::string line, key, says;
  };
  const std::vector<Case> cases{
      {"height_shares = [0.95, 1.5]", "analysis.bed.height_shares", "(0, 1]"},
      {"threshold = 0.0", "analysis.bed.threshold", "(0, 1)"},
      {"bin = 0.02", "analysis.bed.bin", "(0, 0.016]"},
      {"start = -1.0", "analysis.bed.start", "[0, inf)"},
      {"probe_heights = [0.02]", "analysis.bed.probe_heights", "[0, 0.016]"},
      {"map_axis = \"z\"", "analysis.bed.map_axis", "vertical"},
      {"map_bins = [2.5, 3]", "analysis.bed.map_bins", "whole numbers"},
      {"map_thickness = 0.005", "analysis.bed.map_thickness", "(0, 0.004]"},
      {"map_centre = 0.005", "analysis.bed.map_centre", "[0, 0.004]"},
      {"colour = 1", "analysis.bed.colour", "unknown"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.line);
    scene("bad.toml", base + c.line + "\n");
    EXPECT_EQ(carom("check bad.toml"), 2) << out_;
    EXPECT_NE(out_.find(line), std::string::npos) << out_;
    EXPECT_NE(out_.find(c.key), std::string::npos) << out_;
    EXPECT_NE(out_.find(c.says), std::string::npos) << out_;
  }
  // A probe outside the domain, and probes without a gas.
  std::string outside = kGasBed;
  outside.replace(outside.find("[0.002, 0.002, 0.01]"), 20, "[0.002, 0.002, 0.02]");
  scene("outside.toml", outside);
  EXPECT_EQ(carom("check outside.toml"), 2);
  EXPECT_NE(out_.find("outside.toml:41"), std::string::npos) << out_;
  EXPECT_NE(out_.find("analysis.bed.probes"), std::string::npos) << out_;
  EXPECT_NE(out_.find("point 2 with z = 0.02 outside the domain, allowed range [0, 0.016]"),
            std::string::npos)
      << out_;
  std::string dry = kGasBed;
  dry.erase(dry.find("[flight]"), dry.find("[initial]") - dry.find("[flight]"));
  scene("dry.toml", dry);
  EXPECT_EQ(carom("check dry.toml"), 2);
  EXPECT_NE(out_.find("analysis.bed.probes"), std::string::npos) << out_;
  EXPECT_NE(out_.find("no [gas]"), std::string::npos) << out_;
}

}  // namespace
}  // namespace carom_cli_test
