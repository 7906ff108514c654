// Profiles across sections and plugs through the `carom` command line: in a homogeneous elastic
// gas every bin's solid fraction is the gas's and every velocity component spreads by
// sqrt(T / m); a run ended and resumed writes the same profile sums, axial profiles and plug
// heights bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_support.hpp"
#include "core/hdf5.hpp"
#include "scenarios/analysis/section_profiles.hpp"

namespace carom_cli_test {
namespace {

// Elastic spheres of m = 1 kg, d = 1 m at phi = 0.2 in a periodic box of 10 m (about 382), at
// T = 1 J: a Maxwellian with <v_k^2> = T / m = 1 m^2/s^2 in every component, kept by elastic
// collisions (energy is conserved exactly), and a uniform density.
const std::string kGas = R"(
[domain]
min = [0, 0, 0]
max = [10, 10, 10]
periodic = ["x", "y", "z"]
gravity = [0, 0, 0]
[[species]]
name = "sphere"
diameter = 1.0
density = 1.909859317102744
fill = { volume_fraction = 0.2 }
[collisions]
default = { e = 1.0, mu = 0.0, beta0 = -1.0 }
[initial]
seed = 5
temperature = 1.0
[time]
end = 120.0
[output]
snapshot_every = 0
sample_every = 0.25
[analysis.profiles]
heights = [2.5, 7.5]
thickness = 5.0
axis = "x"
bins = 2
start = 1.0
)";

TEST_F(Cli, ProfilesOfAHomogeneousGas) {
  scene("gas.toml", kGas);
  ASSERT_EQ(carom("run gas.toml --out run --quiet"), 0) << out_;
  const carom::h5::File file = carom::h5::File::open((dir_ / "run" / "run.h5").string(), false);
  const carom::h5::Group setup = file.open_group("analysis").open_group("profiles");
  carom::ProfileGeometry g;
  g.heights = setup.read<double>("heights");
  g.thickness = setup.attribute<double>("thickness");
  g.vertical = static_cast<int>(setup.attribute<std::int64_t>("vertical_axis"));
  g.axis = static_cast<int>(setup.attribute<std::int64_t>("bin_axis"));
  g.bins = static_cast<int>(setup.attribute<std::int64_t>("bins"));
  g.lower = setup.attribute<double>("lower");
  g.upper = setup.attribute<double>("upper");
  g.depth = setup.attribute<double>("depth");
  g.start = setup.attribute<double>("start");
  ASSERT_EQ(g.vertical, 2);
  ASSERT_EQ(g.axis, 0);
  ASSERT_DOUBLE_EQ(g.depth, 10.0);
  const carom::h5::Group series = file.open_group("timeseries");
  const carom::ProfileConclusions c =
      carom::conclude_profiles(g, series.read<double>("time"), series.read<double>("profile_sums"));
  ASSERT_EQ(c.samples, 477u);  // t = 1.0, 1.25, ..., 120
  // The four bins (2 sections x 2 bins) each hold a quarter of the box: about 95 particles per
  // sample, 477 samples. A bin's momentum and count decorrelate over about 1 s (measured on 5
  // seeds: autocorrelation of the per-sample mean velocity 0.65 at 0.25 s, 0.2 at 1 s, a tail of
  // 0.1 beyond), so the run holds about 100 independent samples.
  // Density: the count in a quarter of a hard-sphere fluid at phi = 0.2 fluctuates by
  // sqrt(S(0) N) with S(0) = 0.33 (Carnahan-Starling), about 6 % per sample, 0.6 % over 100:
  // 3 % is five standard errors. Means: the per-sample mean of a component spreads by
  // 1 / sqrt(95) = 0.10 m/s (0.083-0.091 measured), 0.01 m/s over 100 samples; 0.06 is five to six
  // standard errors for the largest of 12 components (0.015-0.038 on seeds 1-5). Spread: a
  // Gaussian component's sample spread from about 10 000 independent particle samples is good
  // to 0.7 %; 4 % leaves room for the correlation (0.6-1.6 % on seeds 1-5).
  for (const carom::SectionProfile& s : c.sections)
    for (int b = 0; b < g.bins; ++b) {
      SCOPED_TRACE("section z = " + std::to_string(s.height) + ", bin " + std::to_string(b));
      EXPECT_NEAR(s.solid_fraction[b], 0.2, 0.2 * 0.03);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(s.std_velocity[b][k], 1.0, 0.04);
        EXPECT_NEAR(s.mean_velocity[b][k], 0.0, 0.06);
      }
    }
  // summary.json and report.md carry them.
  EXPECT_NE(read(dir_ / "run" / "summary.json").find("\"profiles\": {\"axis\": \"x\""),
            std::string::npos);
  EXPECT_NE(read(dir_ / "run" / "report.md").find("## Profiles across sections"),
            std::string::npos);
}

TEST_F(Cli, ProfileSumsResumeBitForBit) {
  scene("gas.toml", kGas);
  ASSERT_EQ(carom("run gas.toml --set time.end=4 --out whole --quiet"), 0) << out_;
  ASSERT_EQ(carom("run gas.toml --set time.end=1.5 --out part --quiet"), 0) << out_;
  ASSERT_EQ(carom("resume part --end 4 --quiet"), 0) << out_;
  const auto sums = [&](const char* run) {
    const carom::h5::File file = carom::h5::File::open((dir_ / run / "run.h5").string(), false);
    return file.open_group("timeseries").read<double>("profile_sums");
  };
  const std::vector<double> a = sums("whole"), b = sums("part");
  ASSERT_EQ(a.size(), 17u * 44u);
  EXPECT_EQ(a, b);
}

TEST_F(Cli, PlugSeriesResumeBitForBit) {
  const std::string column = std::string(CAROM_SCENES_DIR) + "/column_1d.toml";
  const std::string sets =
      " --set analysis.plugs.threshold=0.3 --set initial.settle_time=0.01 --quiet";
  ASSERT_EQ(carom("run " + column + sets + " --set time.end=0.06 --out whole"), 0) << out_;
  ASSERT_EQ(carom("run " + column + sets + " --set time.end=0.03 --out part"), 0) << out_;
  ASSERT_EQ(carom("resume part --end 0.06 --quiet"), 0) << out_;
  for (const char* name : {"time", "axial_solid_fraction", "plug_height"}) {
    const auto read_series = [&](const char* run) {
      const carom::h5::File file = carom::h5::File::open((dir_ / run / "run.h5").string(), false);
      return file.open_group("timeseries").read<double>(name);
    };
    const std::vector<double> a = read_series("whole"), b = read_series("part");
    EXPECT_FALSE(a.empty()) << name;
    EXPECT_EQ(a, b) << name;
  }
  // 80 bins of 1 mm, 300 beads, 31 samples (every 2 ms to 0.06 s).
  const carom::h5::File file = carom::h5::File::open((dir_ / "whole" / "run.h5").string(), false);
  EXPECT_EQ(file.open_group("timeseries").read<double>("axial_solid_fraction").size(), 80u * 31u);
  EXPECT_EQ(file.open_group("timeseries").read<double>("plug_height").size(), 300u * 31u);
  EXPECT_NE(read(dir_ / "whole" / "report.md").find("## Plugs"), std::string::npos);
  EXPECT_NE(read(dir_ / "whole" / "summary.json").find("\"plugs\": {\"bin\": 0.001"),
            std::string::npos);
}

TEST_F(Cli, ProfilesRefuseASectionOutsideTheDomainAndBinsAlongTheVertical) {
  std::string outside = kGas;
  outside.replace(outside.find("heights = [2.5, 7.5]"), 20, "heights = [2.5, 12.0]");
  scene("outside.toml", outside);
  EXPECT_EQ(carom("check outside.toml"), 2);
  EXPECT_NE(out_.find("outside.toml:"), std::string::npos) << out_;
  EXPECT_NE(out_.find("analysis.profiles.heights"), std::string::npos) << out_;
  EXPECT_NE(out_.find("[0, 10]"), std::string::npos) << out_;
  std::string vertical = kGas;
  vertical.replace(vertical.find("axis = \"x\""), 10, "axis = \"z\"");
  scene("vertical.toml", vertical);
  EXPECT_EQ(carom("check vertical.toml"), 2);
  EXPECT_NE(out_.find("analysis.profiles.axis"), std::string::npos) << out_;
  EXPECT_NE(out_.find("vertical"), std::string::npos) << out_;
}

}  // namespace
}  // namespace carom_cli_test
