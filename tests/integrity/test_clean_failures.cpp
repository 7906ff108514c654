// Absurd states are refused or detected, and outputs cost what they weigh:
// - `carom check` and `carom run` refuse (exit 2) a temperature, a velocity or a spin above the
//   speed bound (1e6 m/s) or not finite, naming the key.
// - A run whose simulated time stops advancing (less than 1e-8 of its length per watch window;
//   the window shortened to 1 s here through CAROM_STALL_WINDOW_SECONDS) stops with exit 1,
//   status "stalled" and a message naming the cause; the watch's timer changes no bit of a run.
// - A meta.name of 70 kB exits 2 and leaves nothing behind, so the corrected rerun runs.
// - run.xmf grows by appending each snapshot before its closing tail (the file is never
//   rewritten: same inode) and ends byte for byte as a whole rewrite would write it.
// - A run whose estimated output exceeds output.warn_bytes warns first, naming the keys.
#include <sys/stat.h>

#include "scenarios/run/xdmf_sidecar.hpp"
#include "tests/integrity/integrity_support.hpp"

namespace {

using namespace carom_integrity_test;

using CleanFailures = IntegrityCli;

TEST_F(CleanFailures, AbsurdSpeedsTemperaturesAndSpinsAreRefusedByCheckAndRun) {
  const std::string gas = scene("gas.toml", kGas);
  for (const std::string command : {"check ", "run "}) {
    EXPECT_EQ(carom(command + gas + " --set initial.temperature=1e300"), 2) << out_;
    EXPECT_NE(out_.find("initial.temperature"), std::string::npos) << out_;
    EXPECT_NE(out_.find("above the bound of 1e+06 m/s"), std::string::npos) << out_;
    EXPECT_EQ(carom(command + gas + " --set initial.temperature=0 --set initial.rms_velocity=2e6"), 2) << out_;
    EXPECT_NE(out_.find("initial.rms_velocity"), std::string::npos) << out_;
  }
  const std::string one =
      "[domain]\nmin = [0, 0, 0]\nmax = [4, 4, 4]\n[[species]]\nname = \"a\"\ndiameter = 1.0\ndensity = 1000\n"
      "[[particles]]\nspecies = \"a\"\nposition = [2, 2, 2]\n";
  scene("fast.toml", one + "velocity = [1e300, 0, 0]\n[time]\nend = 1\n");
  EXPECT_EQ(carom("check fast.toml"), 2) << out_;
  EXPECT_NE(out_.find("[[particles]] entry at fast.toml"), std::string::npos) << out_;
  scene("spin.toml", one + "spin = [0, 0, 3e6]\n[time]\nend = 1\n");
  EXPECT_EQ(carom("run spin.toml --quiet"), 2) << out_;
  EXPECT_NE(out_.find("surface speed"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "spin.out"));
}

TEST_F(CleanFailures, ARunWhoseTimeStopsAdvancingStopsWithItsCause) {
  scene("gas.toml", kGas);
  // An elastic gas asked to reach 1e12 s advances about 1e3 s per second of wall time: far
  // below 1e-8 of its length per window.
  EXPECT_EQ(carom("run gas.toml --out stall --quiet --set time.end=1e12 --set 'collisions.default={ e = 1.0 }' "
                  "--set output.snapshot_every=1e11 --set output.sample_every=1e11",
                  "CAROM_STALL_WINDOW_SECONDS=1"),
            1)
      << out_;
  EXPECT_NE(out_.find("the run has stalled"), std::string::npos) << out_;
  EXPECT_NE(out_.find("The fastest particle moves at"), std::string::npos) << out_;
  EXPECT_EQ(out_.find("inelastic collapse"), std::string::npos) << out_;
  EXPECT_NE(read(dir_ / "stall" / "summary.json").find("\"status\": \"stalled\""), std::string::npos);
}

TEST_F(CleanFailures, TheWatchTimerChangesNoBitOfARun) {
  scene("gas.toml", kGas);
  for (const std::string& method : kMethods) {
    SCOPED_TRACE(method);
    const std::string args = "run gas.toml --quiet --method " + method + " --set time.end=" +
                             (method == "soft_sphere" ? "4" : "60") +
                             " --set 'collisions.default={ e = 1.0 }' --set monte_carlo.time_step=0.005";
    ASSERT_EQ(carom(args + " --out plain_" + method), 0) << out_;
    // A look every 0.1 s: run_until is made to return many times in the run.
    ASSERT_EQ(carom(args + " --out watched_" + method, "CAROM_STALL_WINDOW_SECONDS=0.1"), 0) << out_;
    const carom::h5::File a = carom::h5::File::open((dir_ / ("plain_" + method) / "checkpoint.h5").string(), false);
    const carom::h5::File b = carom::h5::File::open((dir_ / ("watched_" + method) / "checkpoint.h5").string(), false);
    for (const char* name : {"position", "velocity", "spin"})
      EXPECT_EQ(a.open_group("state/particles").read<double>(name), b.open_group("state/particles").read<double>(name))
          << name;
  }
}

TEST_F(CleanFailures, AHugeSceneNameExitsTwoAndLeavesNothingBehind) {
  scene("named.toml", "[meta]\nname = \"" + std::string(70000, 'x') + "\"\n" + kGas);
  EXPECT_EQ(carom("run named.toml --out named --quiet"), 2) << out_.substr(0, 400);
  EXPECT_NE(out_.find("meta.name"), std::string::npos) << out_.substr(0, 400);
  EXPECT_LT(out_.size(), 1000u) << "the error quotes the whole name";
  EXPECT_FALSE(fs::exists(dir_ / "named"));
  scene("named.toml", "[meta]\nname = \"short\"\n" + kGas);
  EXPECT_EQ(carom("run named.toml --out named --quiet"), 0) << out_;
}

TEST_F(CleanFailures, RunXmfGrowsByAppendingAndEndsAsAWholeRewrite) {
  const std::string h5 = (dir_ / "run.h5").string(), xmf = (dir_ / "run.xmf").string();
  std::vector<carom::XdmfSnapshot> snapshots{{"000000", 0.0, 10}};
  carom::write_xdmf_sidecars(h5, snapshots, nullptr);
  struct stat first {};
  ASSERT_EQ(stat(xmf.c_str(), &first), 0);
  for (int k = 1; k < 50; ++k) {
    char name[8];
    std::snprintf(name, sizeof name, "%06d", k);
    snapshots.push_back({name, 0.1 * k, 10});
    ASSERT_TRUE(carom::append_xdmf_snapshot(h5, snapshots.back(), nullptr));
  }
  struct stat last {};
  ASSERT_EQ(stat(xmf.c_str(), &last), 0);
  EXPECT_EQ(first.st_ino, last.st_ino) << "the sidecar was rewritten, not appended to";
  const std::string appended = read(xmf);
  carom::write_xdmf_sidecars(h5, snapshots, nullptr);
  EXPECT_EQ(read(xmf), appended);
  // A sidecar that does not end as carom writes it is not appended to (the caller rewrites it).
  std::ofstream(xmf, std::ios::app) << "<!-- edited -->\n";
  EXPECT_FALSE(carom::append_xdmf_snapshot(h5, {"000050", 5.0, 10}, nullptr));
}

TEST_F(CleanFailures, ALargeOutputIsAnnouncedWithTheKeysThatSetIt) {
  scene("gas.toml", kGas);
  EXPECT_EQ(carom("run gas.toml --out big --set output.warn_bytes=1e5"), 0) << out_;
  EXPECT_NE(out_.find("warning: gas.toml: the run will write about"), std::string::npos) << out_;
  EXPECT_NE(out_.find("output.snapshot_every"), std::string::npos) << out_;
  EXPECT_NE(out_.find("output.warn_bytes"), std::string::npos) << out_;
  EXPECT_EQ(carom("run gas.toml --out small"), 0) << out_;
  EXPECT_EQ(out_.find("warning"), std::string::npos) << out_;
}

}  // namespace
