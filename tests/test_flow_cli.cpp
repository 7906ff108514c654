// Inflow and outflow through the command line, with every method, on the shipped
// scenarios/scenes/duct_flow.toml: 3 mm glass fed at rest at 0.13 kg/s (3678 beads/s) from a
// slab 1 cm thick under z = 0.79 m, falling to an outlet at z = 0.08 m.
//
// - Mass in: the inflow places what it owes at each flow step (every 1 ms), the whole
//   particles of mass_flow (t - 0) / m, so at a sample at t the entered mass is within one flow
//   step's worth plus one particle of mass_flow t (exact bookkeeping, no statistics).
// - Counts: particles present = entered - left, exactly, at every sample.
// - Energy: kinetic + potential + dissipated - flow (what entering particles brought minus what
//   leaving ones took) is constant: to round-off for the event-driven and Monte Carlo methods
//   (1e-12 of the largest kinetic energy; measured 4e-14), and to the soft spheres' O(dt^2)
//   integration error (1e-6 of it; measured 8e-8).
// - Steady state: the beads fall freely (0.7 collisions each on the way, momentum-conserving
//   between beads; 0.08 wall impacts), so the number present is the feed rate times the mean
//   free-fall time from the slab to the outlet, plus half a flow step (beads leave at the first
//   step after crossing): 3678.25 * (0.379118 + 0.0005) = 1396.3. Measured over t >= 0.42 s:
//   1396.9 (event-driven), 1397.1 (soft spheres), 1398.9 (Monte Carlo), sd 3-6 between samples;
//   the tolerance 0.5 % (7 beads) covers the sampling spread (3 standard errors of the mean
//   of 4 samples: 4.5) and leaves collisions and wall friction, which slow the fall by far
//   less, room to show if they were modelled wrong (a bead slowed by 5 % would add 19).
// - Resume: a run stopped at 0.2 s and resumed to 0.45 s writes the same series bit for bit.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "core/hdf5.hpp"

using namespace carom_cli_test;

namespace {

const char* const kMethods[] = {"event_driven", "soft_sphere", "monte_carlo"};

std::string duct() {
  return kScenes + "/duct_flow.toml";
}

}  // namespace

TEST_F(Cli, DuctFlowWithEveryMethod) {
  const double mass_flow = 0.13, interval = 1e-3;
  const double bead = 2500.0 * std::numbers::pi / 6.0 * 27e-9;  // kg
  for (const char* method : kMethods) {
    SCOPED_TRACE(method);
    const std::string out = std::string("run_") + method;
    ASSERT_EQ(carom("run " + duct() + " --set method.kind='\"" + method +
                    "\"' --set time.end=0.45 --out " + out + " --quiet"),
              0)
        << out_;
    const fs::path run = dir_ / out, run_file = run / "run.h5";
    const auto t = timeseries(run_file, "time"), in = timeseries(run_file, "entered_mass"),
               out_mass = timeseries(run_file, "left_mass");
    const auto entered = timeseries(run_file, "entered"), left = timeseries(run_file, "left"),
               present = timeseries(run_file, "particles_present");
    const auto total = timeseries(run_file, "total_energy"),
               kinetic = timeseries(run_file, "kinetic_translational");
    ASSERT_EQ(t.size(), 46u);
    double kinetic_max = 0, drift = 0, steady = 0;
    int steady_samples = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      EXPECT_LE(std::abs(in[k] - mass_flow * t[k]), mass_flow * interval + bead) << "t = " << t[k];
      EXPECT_EQ(present[k], entered[k] - left[k]) << "t = " << t[k];
      kinetic_max = std::max(kinetic_max, kinetic[k]);
      drift = std::max(drift, std::abs(total[k] - total[0]));
      if (t[k] >= 0.42 - 1e-9) {
        steady += present[k];
        ++steady_samples;
      }
    }
    EXPECT_GT(left.back(), 100.0);  // the outflow works
    EXPECT_NEAR(out_mass.back(), left.back() * bead, 1e-9 * out_mass.back());
    EXPECT_LT(drift, (std::string(method) == "soft_sphere" ? 1e-6 : 1e-12) * kinetic_max);
    ASSERT_EQ(steady_samples, 4);
    EXPECT_NEAR(steady / steady_samples, 1396.3, 0.005 * 1396.3);
    const std::string summary = read(run / "summary.json");
    EXPECT_NE(summary.find("\"flow\": {\"inflows\": [{\"name\": \"feed\", \"set_mass_flow\": 0.13"),
              std::string::npos);
  }
}

TEST_F(Cli, DuctFlowResumesBitForBit) {
  for (const char* method : kMethods) {
    SCOPED_TRACE(method);
    const std::string set = " --set method.kind='\"" + std::string(method) + "\"' --quiet";
    const std::string whole = std::string("whole_") + method, part = std::string("part_") + method;
    ASSERT_EQ(carom("run " + duct() + set + " --set time.end=0.45 --out " + whole), 0) << out_;
    ASSERT_EQ(carom("run " + duct() + set + " --set time.end=0.2 --out " + part), 0) << out_;
    ASSERT_EQ(carom("resume " + part + " --end 0.45 --quiet"), 0) << out_;
    for (const char* name :
         {"time", "particles_present", "entered_mass", "left_mass", "particle_seconds",
          "total_energy", "kinetic_translational", "flow_energy", "pair_collisions"}) {
      const auto a = timeseries(dir_ / whole / "run.h5", name),
                 b = timeseries(dir_ / part / "run.h5", name);
      EXPECT_FALSE(a.empty()) << name;
      EXPECT_EQ(a, b) << name;
    }
  }
}
