// Tagged bodies through the `carom` command line: a run ended at T and resumed with
// `carom resume --end` writes the same tagged-body series, bit for bit, as the uninterrupted run
// (the books come from the checkpoint, the previous sample's impulse from run.h5), and
// summary.json gets the same fit.
#include <gtest/gtest.h>

#include <cstring>

#include "cli_support.hpp"
#include "core/hdf5.hpp"

namespace carom_cli_test {
namespace {

// A small cloud_drag.toml: a 1.5 mm sphere at 0.5 m/s in a periodic box of glass (about 1100).
const std::string kCloud = R"(
[domain]
min = [0, 0, 0]
max = [0.006, 0.006, 0.009]
periodic = ["x", "y", "z"]
[[species]]
name = "sphere"
diameter = 1.5e-3
density = 500.0
[[species]]
name = "glass"
diameter = 0.3e-3
density = 2500.0
fill = { volume_fraction = 0.05 }
[[particles]]
species = "sphere"
position = [0.003, 0.003, 0.004]
velocity = [0, 0, 0.5]
tagged = true
[collisions]
default = { e = 0.7, mu = 0.3, beta0 = 0.34 }
[initial]
seed = 3
[time]
end = 0.008
[output]
snapshot_every = 0
sample_every = 0.0005
)";

TEST_F(Cli, TaggedSeriesResumeBitForBit) {
  scene("cloud.toml", kCloud);
  ASSERT_EQ(carom("run cloud.toml --out whole --quiet"), 0) << out_;
  ASSERT_EQ(carom("run cloud.toml --set time.end=0.003 --out part --quiet"), 0) << out_;
  ASSERT_EQ(carom("resume part --end 0.008 --quiet"), 0) << out_;
  for (const char* name :
       {"time", "tagged_position", "tagged_velocity", "tagged_impulse", "tagged_force",
        "tagged_force_by_partner", "tagged_mean_velocity", "tagged_mean_force"}) {
    const std::vector<double> a = timeseries(dir_ / "whole" / "run.h5", name);
    const std::vector<double> b = timeseries(dir_ / "part" / "run.h5", name);
    ASSERT_EQ(a.size(), b.size()) << name;
    // memcmp: the first row's forces are NaN (no window yet), and NaN != NaN.
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << name;
  }
  const std::string whole = read(dir_ / "whole" / "summary.json");
  const std::string part = read(dir_ / "part" / "summary.json");
  const auto fit = [](const std::string& s) {
    return s.substr(s.find("\"inverse_speed_fit\""), 200);
  };
  ASSERT_NE(whole.find("\"inverse_speed_fit\""), std::string::npos);
  EXPECT_EQ(fit(whole), fit(part));
}

}  // namespace
}  // namespace carom_cli_test
