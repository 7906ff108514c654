// The `carom` command, run as a user runs it: exit codes, what it writes (and never writes for
// a bad scene), signals, and bit-for-bit resume: a run interrupted at T (by its end time or by
// SIGINT) and resumed must end in exactly the state of the uninterrupted run, particle by
// particle (positions, velocities, spins, clocks compared with ==, not a tolerance: the
// dynamics is deterministic and a checkpoint stores every double as it is).
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>

#include "core/hdf5.hpp"
#include "scenarios/run/run_output.hpp"
#include "checkpoint_support.hpp"
#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace carom;
using namespace carom_cli_test;

extern char** environ;

namespace {

/// Final states by particle id.
std::map<std::uint64_t, std::size_t> by_id(const ParticleStore& p) {
  std::map<std::uint64_t, std::size_t> index;
  for (std::size_t i = 0; i < p.size(); ++i) index[p.id[i]] = i;
  return index;
}

/// Every particle's stored state and the counters are identical, bit for bit.
void expect_identical(const Checkpoint& checkpoint_a, const Checkpoint& checkpoint_b) {
  const EngineState a = saved_engine_state(checkpoint_a), b = saved_engine_state(checkpoint_b);
  ASSERT_EQ(a.time, b.time);
  const ParticleStore& p = a.particles;
  const ParticleStore& q = b.particles;
  ASSERT_EQ(p.size(), q.size());
  const auto ia = by_id(p), ib = by_id(q);
  std::size_t differing = 0;
  for (const auto& [id, i] : ia) {
    const std::size_t j = ib.at(id);
    const bool same = p.position[i] == q.position[j] && p.velocity[i] == q.velocity[j] && p.spin[i] == q.spin[j] &&
                      p.clock[i] == q.clock[j] && a.event_counters[i] == b.event_counters[j];
    if (!same && differing++ < 3)
      ADD_FAILURE() << "particle " << id << " differs: position " << p.position[i].transpose() << " vs "
                    << q.position[j].transpose();
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(a.statistics.events, b.statistics.events);
  EXPECT_EQ(a.statistics.pair_collisions, b.statistics.pair_collisions);
  EXPECT_EQ(a.statistics.dissipated_energy, b.statistics.dissipated_energy);
}


}  // namespace

TEST_F(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(carom(""), 2) << out_;
  EXPECT_EQ(carom("fly scene.toml"), 2) << out_;
  EXPECT_EQ(carom("run"), 2) << out_;
  EXPECT_EQ(carom("run x.toml --bogus"), 2) << out_;
  EXPECT_EQ(carom("--help"), 0) << out_;
  EXPECT_NE(out_.find("Exit codes"), std::string::npos);
  EXPECT_EQ(carom("run missing.toml"), 2) << out_;
  EXPECT_NE(out_.find("missing.toml: cannot open"), std::string::npos) << out_;
  EXPECT_EQ(carom("resume nowhere"), 2) << out_;
  EXPECT_EQ(carom("info nothing.h5"), 2) << out_;
}

TEST_F(Cli, CheckShippedScenes) {
  for (const char* name : {"elastic_gas", "haff_cooling", "bidisperse_gas", "settling_column", "settling_sphere",
                           "packed_bed", "fluidized_bed", "column_1d", "bubbling_bed", "fines_bed",
                           "narrow_tube"}) {
    EXPECT_EQ(carom("check '" + kScenes + "/" + name + ".toml'"), 0) << name << ": " << out_;
    EXPECT_NE(out_.find("grid"), std::string::npos);
  }
  EXPECT_EQ(carom("check '" + kScenes + "/elastic_gas.toml'"), 0);
  EXPECT_NE(out_.find("rotation: off"), std::string::npos) << out_;
  EXPECT_NE(out_.find("Enskog"), std::string::npos) << out_;
  EXPECT_EQ(carom("check '" + kScenes + "/fluidized_bed.toml'"), 0);
  EXPECT_NE(out_.find("gas coupling: two-way"), std::string::npos) << out_;
  EXPECT_NE(out_.find("U_mf"), std::string::npos) << out_;
  // The scenes that start empty and fill through an inflow: check lists the inflow and outflow.
  for (const char* name : {"duct_flow", "convergent_duct"}) {
    EXPECT_EQ(carom("check '" + kScenes + "/" + name + ".toml'"), 0) << name << ": " << out_;
    EXPECT_NE(out_.find("inflow \"feed\": glass at"), std::string::npos) << out_;
    EXPECT_NE(out_.find("outflow \"exit\": centres below z"), std::string::npos) << out_;
  }
  EXPECT_TRUE(fs::is_empty(dir_)) << "check must write nothing";
}

TEST_F(Cli, BadSceneExitsTwoAndLeavesNothing) {
  // The error is found only after parsing (an overlap of listed particles): still nothing written.
  const std::string bad = scene("bad.toml",
                                "[domain]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n"
                                "[[species]]\nname = \"a\"\ndiameter = 0.1\ndensity = 1000\n"
                                "[[particles]]\nspecies = \"a\"\nposition = [0.5, 0.5, 0.5]\n"
                                "[[particles]]\nspecies = \"a\"\nposition = [0.55, 0.5, 0.5]\n"
                                "[time]\nend = 1\n");
  EXPECT_EQ(carom("run " + bad + " --out result"), 2) << out_;
  EXPECT_NE(out_.find("overlaps"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "result"));
  EXPECT_FALSE(fs::exists(dir_ / "bad.out"));
  const std::string typo = scene("typo.toml", kSmallGas + "[engine]\ngrid_ratio = 0.5\n");
  EXPECT_EQ(carom("run " + typo), 2) << out_;
  EXPECT_NE(out_.find("typo.toml:"), std::string::npos) << out_;
  EXPECT_NE(out_.find("did you mean 'engine.grid_level_ratio'"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "typo.out"));
  // A bad --set is a bad scene too.
  EXPECT_EQ(carom("run " + scene("gas.toml", kSmallGas) + " --set collisions.default.e=1.5"), 2) << out_;
  EXPECT_NE(out_.find("collisions.default.e = 1.5"), std::string::npos) << out_;
  EXPECT_FALSE(fs::exists(dir_ / "gas.out"));
}

TEST_F(Cli, RunWritesOutputsAndRefusesToOverwrite) {
  const std::string gas = scene("gas.toml", kSmallGas);
  ASSERT_EQ(carom("run " + gas + " --out r --quiet --set time.end=1.0"), 0) << out_;
  for (const char* file : {"run.h5", "run.xmf", "checkpoint.h5", "summary.json"}) EXPECT_TRUE(fs::exists(dir_ / "r" / file)) << file;
  const std::string summary = read(dir_ / "r" / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"completed\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"end_time\": 1,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"a-b\""), std::string::npos) << summary;
  const auto written = fs::last_write_time(dir_ / "r" / "run.h5");
  EXPECT_EQ(carom("run " + gas + " --out r --quiet"), 2) << out_;
  EXPECT_NE(out_.find("already holds"), std::string::npos) << out_;
  EXPECT_EQ(fs::last_write_time(dir_ / "r" / "run.h5"), written);
  EXPECT_EQ(carom("info r/run.h5"), 0) << out_;
  EXPECT_NE(out_.find("snapshots"), std::string::npos) << out_;
  EXPECT_EQ(carom("info r/checkpoint.h5"), 0) << out_;
  EXPECT_EQ(carom("resume r --quiet"), 0) << out_;  // already at its end: nothing to do
  EXPECT_EQ(carom("resume r --end 0.5 --quiet"), 2) << out_;  // before the checkpoint
}

TEST_F(Cli, CollapseExitsOne) {
  // Three nearly inelastic spheres on a line (e = 0.05, below the 1-D collapse threshold
  // 7 - 4 sqrt(3) = 0.072): the collision sequence converges in finite time, the stall detector fires.
  const std::string line = scene("line.toml",
                                 "[domain]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n"
                                 "[[species]]\nname = \"ball\"\ndiameter = 0.1\ndensity = 1000\n"
                                 "[[particles]]\nspecies = \"ball\"\nposition = [0.3, 0.5, 0.5]\nvelocity = [1, 0, 0]\n"
                                 "[[particles]]\nspecies = \"ball\"\nposition = [0.5, 0.5, 0.5]\n"
                                 "[[particles]]\nspecies = \"ball\"\nposition = [0.7, 0.5, 0.5]\nvelocity = [-0.2, 0, 0]\n"
                                 "[collisions]\ndefault = { e = 0.05 }\ncollapse = { stall_collisions = 100 }\n"
                                 "[time]\nend = 2\n");
  EXPECT_EQ(carom("run " + line + " --out c --quiet"), 1) << out_;
  EXPECT_NE(out_.find("inelastic collapse"), std::string::npos) << out_;
  EXPECT_NE(read(dir_ / "c" / "summary.json").find("\"status\": \"inelastic_collapse\""), std::string::npos);
}

TEST_F(Cli, ResumeAfterEndTimeIsBitForBit) {
  const std::string gas = scene("gas.toml", kSmallGas);
  ASSERT_EQ(carom("run " + gas + " --out whole --quiet"), 0) << out_;
  ASSERT_EQ(carom("run " + gas + " --out split --quiet --set time.end=2.0"), 0) << out_;
  ASSERT_EQ(carom("resume split --end 4.0 --quiet"), 0) << out_;
  expect_identical(read_checkpoint((dir_ / "whole" / "checkpoint.h5").string()),
                   read_checkpoint((dir_ / "split" / "checkpoint.h5").string()));
}

// A checkpoint names the method whose state it holds; resuming it with a scene of another method
// is refused (exit 2) with both names, before anything is written.
TEST_F(Cli, ResumeRefusesAnotherMethodsState) {
  const std::string gas = scene("gas.toml", kSmallGas);
  ASSERT_EQ(carom("run " + gas + " --out a --quiet --set time.end=1.0"), 0) << out_;
  const std::string checkpoint = (dir_ / "a" / "checkpoint.h5").string();
  {
    const h5::File file = h5::File::open(checkpoint, true);
    EXPECT_EQ(file.open_group("state").attribute<std::string>("method"), "event_driven");
    file.open_group("state").set_attribute("method", std::string("soft_sphere"));
  }
  const std::string summary_before = read(dir_ / "a" / "summary.json");
  EXPECT_EQ(carom("resume a --end 2.0 --quiet"), 2) << out_;
  EXPECT_NE(out_.find("method 'soft_sphere'"), std::string::npos) << out_;
  EXPECT_NE(out_.find("'event_driven'"), std::string::npos) << out_;
  EXPECT_EQ(read(dir_ / "a" / "summary.json"), summary_before) << "nothing already written is lost";
}

TEST_F(Cli, ResumeAfterSigintIsBitForBit) {
  // A run long enough to be interrupted mid-way; SIGINT makes it checkpoint and exit 130.
  const std::string gas = scene("gas.toml", kSmallGas);
  pid_t pid = 0;
  const std::string out_arg = (dir_ / "split").string();
  std::vector<std::string> args{kCarom, "run", (dir_ / gas).string(), "--out", out_arg, "--quiet", "--set", "time.end=100000"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  ASSERT_EQ(posix_spawn(&pid, kCarom.c_str(), nullptr, nullptr, argv.data(), environ), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 130);
  const Checkpoint stopped = read_checkpoint((dir_ / "split" / "checkpoint.h5").string());
  EXPECT_NE(read(dir_ / "split" / "summary.json").find("\"status\": \"interrupted\""), std::string::npos);
  ASSERT_GT(saved_engine_state(stopped).time, 0.0);
  // Continue a little past the interruption and compare with a run that never stopped.
  const std::string end = std::to_string(std::ceil(saved_engine_state(stopped).time) + 1.0);
  ASSERT_EQ(carom("resume split --end " + end + " --quiet"), 0) << out_;
  ASSERT_EQ(carom("run " + gas + " --out whole --quiet --set time.end=" + end), 0) << out_;
  expect_identical(read_checkpoint((dir_ / "whole" / "checkpoint.h5").string()),
                   read_checkpoint((dir_ / "split" / "checkpoint.h5").string()));
}

// A coupled run (gas solver, fluid steps as global events, relax flights) resumed from its
// checkpoint ends in exactly the state of the uninterrupted run, particles and gas alike. Four
// packings: a relax prediction's last bits depend on the order a cell's particles are examined
// in (each candidate is searched up to the best time so far), so the checkpoint must keep the
// cells' list order. Rebuilt in particle order instead, seed 1 here diverged in round-off, and
// so did the fines bed of FinesBedAnalysisSurvivesResume for seeds 2, 3 and 4.
TEST_F(Cli, ResumeWithGasIsBitForBit) {
  for (int seed : {1, 2, 3, 4}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::string bed = "'" + kScenes + "/fluidized_bed.toml' --quiet --set species.glass.fill.count=150 "
                            "--set 'domain.max=[0.008, 0.004, 0.03]' --set 'regions.bed.max=[0.008, 0.004, 0.015]' "
                            "--set 'gas.cells=[4, 1, 10]' --set gas.boundaries.z_low.ramp_time=0.01 "
                            "--set initial.settle_time=0.05 --seed " + std::to_string(seed);
    const std::string whole_dir = "whole" + std::to_string(seed), split_dir = "split" + std::to_string(seed);
    ASSERT_EQ(carom("run " + bed + " --out " + whole_dir + " --set time.end=0.04"), 0) << out_;
    ASSERT_EQ(carom("run " + bed + " --out " + split_dir + " --set time.end=0.02"), 0) << out_;
    ASSERT_EQ(carom("resume " + split_dir + " --end 0.04 --quiet"), 0) << out_;
    const Checkpoint whole = read_checkpoint((dir_ / whole_dir / "checkpoint.h5").string());
    const Checkpoint split = read_checkpoint((dir_ / split_dir / "checkpoint.h5").string());
    expect_identical(whole, split);
    ASSERT_TRUE(whole.has_gas());
    ASSERT_FALSE(saved_gas_arrays(whole).empty());
    EXPECT_TRUE(saved_gas_arrays(whole) == saved_gas_arrays(split)) << "the gas fields differ";
    EXPECT_GT(saved_engine_state(whole).statistics.pair_events, 100u) << "the beads must collide";
  }
}

// The main job's analysis (mixing, dispersion, collision frequencies, mechanism) always covers
// the run from t = 0: a run interrupted and resumed must report exactly what the uninterrupted
// one reports, in summary.json's "analysis" and in report.md (tags and history are read back).
TEST_F(Cli, FinesBedAnalysisSurvivesResume) {
  const std::string bed = "'" + kScenes + "/fines_bed.toml' --quiet --set species.large.fill.count=200 "
                          "--set initial.settle_time=0.05 --set output.sample_every=0.005 "
                          "--set gas.boundaries.z_low.ramp_time=0.01";
  ASSERT_EQ(carom("run " + bed + " --out whole --set time.end=0.04"), 0) << out_;
  ASSERT_EQ(carom("run " + bed + " --out split --set time.end=0.02"), 0) << out_;
  ASSERT_EQ(carom("resume split --end 0.04 --quiet"), 0) << out_;
  auto analysis = [&](const char* run) {
    const std::string summary = read(dir_ / run / "summary.json");
    const std::size_t at = summary.find("\"analysis\":");
    return at == std::string::npos ? std::string() : summary.substr(at);
  };
  const std::string whole = analysis("whole");
  ASSERT_FALSE(whole.empty()) << "summary.json has no analysis";
  for (const char* key : {"\"mixing\"", "\"dispersion\"", "\"collision_frequency\"", "\"kinetic_theory_frequency\"",
                          "\"granular_temperature\"", "\"segregation_index\"", "\"mechanism\"", "\"large-fines\""})
    EXPECT_NE(whole.find(key), std::string::npos) << key << " missing in " << whole;
  EXPECT_EQ(whole, analysis("split"));
  EXPECT_EQ(read(dir_ / "whole" / "report.md"), read(dir_ / "split" / "report.md"));
  EXPECT_NE(read(dir_ / "whole" / "report.md").find("## Mechanism"), std::string::npos);
}
