// Checkpoints carry their own proof: a damaged value is refused by `carom resume` with exit 2 and
// a message naming the dataset, never a crash and never a completed run from a damaged state.
// - Value checks (the checksum rewritten after the damage, so that only they can catch it): a
//   partner index >= N, a mass of 0 or -1, a radius of 1e84, an inertia of NaN, a speed of
//   1e300 m/s, a NaN time in run.h5, for every method where the dataset exists.
// - Hard spheres overlapping in the restored state refused; a next fluid step before the state's
//   time or more than one step after it refused.
// - A dataset of the state missing (the checksum rewritten) refused, for every method; a soft-
//   sphere drag rate other than 0 in a run without gas refused.
// - The checksum: a changed value with the old checksum, and a checkpoint without one, refused.
// - Identity: run.h5, checkpoint.h5 and summary.json carry one run id; a checkpoint of another
//   run in the folder is refused.
// - An intact checkpoint of every method still resumes (exit 0).
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "tests/integrity/integrity_support.hpp"

namespace {

using namespace carom_integrity_test;

class DamagedCheckpoint : public IntegrityCli {
 protected:
  /// Runs the small gas with `method` to t = 1 s into folder `out`.
  void run_gas(const std::string& method, const std::string& out, const std::string& extra = "") {
    ASSERT_EQ(carom("run " + scene("gas.toml", kGas) + " --method " + method + " --out " + out + " --quiet" + extra), 0)
        << out_;
  }
  /// A copy of folder `from` named `to`, to damage.
  std::string copy_of(const std::string& from, const std::string& to) {
    fs::copy(dir_ / from, dir_ / to, fs::copy_options::recursive);
    return (dir_ / to / "checkpoint.h5").string();
  }
  /// `carom resume` of `out` must exit 2 naming `dataset`, with no crash.
  void expect_refused(const std::string& out, const std::string& dataset) {
    const int code = carom("resume " + out + " --end 1.2 --quiet");
    EXPECT_EQ(code, 2) << out_;
    EXPECT_NE(out_.find(dataset), std::string::npos) << out_;
    EXPECT_EQ(out_.find("completed"), std::string::npos) << out_;
  }
};

TEST_F(DamagedCheckpoint, EachDamagedValueIsRefusedForEveryMethod) {
  for (const std::string& method : kMethods) {
    SCOPED_TRACE(method);
    run_gas(method, method);
    const std::string ckpt = (dir_ / method / "checkpoint.h5").string();
    const carom::h5::File probe = carom::h5::File::open(ckpt, false);
    const std::size_t n = probe.open_group("state/particles").open_dataset("mass").shape()[0];
    const bool events = probe.contains("state/events");

    damage<double>(copy_of(method, method + "_mass0"), "/state/particles/mass", 3, 0.0);
    expect_refused(method + "_mass0", "/state/particles/mass");
    damage<double>(copy_of(method, method + "_mass-1"), "/state/particles/mass", 5, -1.0);
    expect_refused(method + "_mass-1", "/state/particles/mass");
    damage<double>(copy_of(method, method + "_inertia"), "/state/particles/inertia", 7,
                   std::numeric_limits<double>::quiet_NaN());
    expect_refused(method + "_inertia", "/state/particles/inertia");
    damage<double>(copy_of(method, method + "_speed"), "/state/particles/velocity", 4, 1e300);
    expect_refused(method + "_speed", "/state/particles/velocity");
    damage<double>(copy_of(method, method + "_radius"), "/state/particles/radius", 2, -0.5);
    expect_refused(method + "_radius", "/state/particles/radius");
    // A finite, positive but wild radius (fuzz_resume found 1e84 reaching the gas grid's cell
    // index as an int): refused as not the species' radius.
    damage<double>(copy_of(method, method + "_huge_radius"), "/state/particles/radius", 2, 1e84);
    expect_refused(method + "_huge_radius", "/state/particles/radius");
    damage<double>(copy_of(method, method + "_place"), "/state/particles/position", 0, 1e9);
    expect_refused(method + "_place", "/state/particles/position");
    if (events) {
      const long pair = first_of_kind(ckpt, "state/events", 1);
      ASSERT_GE(pair, 0);
      damage<std::int32_t>(copy_of(method, method + "_partner"), "/state/events/partner", pair,
                           static_cast<std::int32_t>(n));
      expect_refused(method + "_partner", "/state/events/partner");
    }
  }
}

TEST_F(DamagedCheckpoint, AnIntactCheckpointOfEveryMethodStillResumes) {
  for (const std::string& method : kMethods) {
    SCOPED_TRACE(method);
    run_gas(method, method);
    EXPECT_EQ(carom("resume " + method + " --end 1.2 --quiet"), 0) << out_;
    EXPECT_NE(read(dir_ / method / "summary.json").find("\"status\": \"completed\""), std::string::npos);
  }
}

TEST_F(DamagedCheckpoint, AChangedValueUnderTheOldChecksumIsRefused) {
  run_gas("event_driven", "run");
  const std::string ckpt = copy_of("run", "flipped");
  double x = carom::h5::File::open(ckpt, false).open_group("state/particles").read<double>("position")[6];
  std::uint64_t bits;
  std::memcpy(&bits, &x, 8);
  bits ^= 1;  // the last bit of the mantissa: a value still inside the box
  std::memcpy(&x, &bits, 8);
  damage<double>(ckpt, "/state/particles/position", 6, x, false);
  expect_refused("flipped", "checksum");
}

TEST_F(DamagedCheckpoint, ACheckpointWithoutChecksumIsRefused) {
  run_gas("monte_carlo", "run");
  const std::string ckpt = copy_of("run", "unsealed");
  {
    const carom::h5::File file = carom::h5::File::open(ckpt, true);
    ASSERT_GE(H5Adelete(file.id(), carom::kChecksumAttribute), 0);
  }
  expect_refused("unsealed", "has no checksum");
}

// Found by tests/fuzz/fuzz_resume: a dataset of the state missing from a sealed checkpoint was
// an HDF5 error (exit 1, "carom: failed"), not a refusal (exit 2).
TEST_F(DamagedCheckpoint, AMissingStateDatasetIsRefused) {
  for (const std::string& method : kMethods) {
    run_gas(method, "run_" + method);
    const std::string ckpt = copy_of("run_" + method, "no_mass_" + method);
    {
      const carom::h5::File file = carom::h5::File::open(ckpt, true);
      file.open_group("state/particles").remove("mass");
      carom::seal_file(file);
    }
    expect_refused("no_mass_" + method, "/state/particles: has no dataset 'mass'");
  }
}

// Found by tests/fuzz/fuzz_resume: a soft-sphere drag rate of 1.6e69 1/s in a run without gas
// made the velocities explode in the first steps and the neighbour grid cast a position of
// 7.8e37 m to a cell index (undefined behaviour).
// Hard spheres that overlap where the checkpoint puts them (each value finite and in the box, so
// only the restored state shows it): particle 1 given particle 0's position, velocity and clock,
// so that both are at one place at the state's time. Refused, naming the positions, instead of
// a run whose engine resolves collisions of an overlapping pair.
TEST_F(DamagedCheckpoint, OverlappingHardSpheresAreRefused) {
  run_gas("event_driven", "overlap_run");
  const std::string ckpt = copy_of("overlap_run", "overlap");
  std::vector<double> position, velocity, clock;
  {
    const carom::h5::File file = carom::h5::File::open(ckpt, false);
    const carom::h5::Group particles = file.open_group("state/particles");
    position = particles.read<double>("position");
    velocity = particles.read<double>("velocity");
    clock = particles.read<double>("clock");
  }
  for (std::size_t a = 0; a < 3; ++a) {
    damage<double>(ckpt, "/state/particles/position", 3 + a, position[a]);
    damage<double>(ckpt, "/state/particles/velocity", 3 + a, velocity[a]);
  }
  damage<double>(ckpt, "/state/particles/clock", 1, clock[0]);
  expect_refused("overlap", "/state/particles/position");
  EXPECT_NE(out_.find("overlaps"), std::string::npos) << out_;
}

// A small gas-fluidized bed's checkpoint, damaged under a re-sealed checksum, for every method: the
// next fluid step's time moved before the state's time (fuzz_resume found the event-driven clock
// sent back to it, and a pair overlapping after) or more than one step after it; a gas speed of
// 1e300 m/s; a porosity of 1.5. Each refused, naming what is wrong.
TEST_F(DamagedCheckpoint, ADamagedGasBedStateIsRefused) {
  for (const std::string& method : kMethods) {
    SCOPED_TRACE(method);
    // A small gas-fluidized bed to t = 5 ms, fluid steps of 0.5 ms (the first action: fluid_step).
    ASSERT_EQ(carom("run " CAROM_TESTS_DIR "/fuzz/resume_gas_bed.toml --method " + method + " --out steps_" + method +
                    " --quiet --set species.glass.young_modulus=1e7"),
              0)
        << out_;
    damage<double>(copy_of("steps_" + method, "step_back_" + method), "/state/actions/next_time", 0, 0.001);
    expect_refused("step_back_" + method, "the next fluid_step at t = 0.001 s");
    damage<double>(copy_of("steps_" + method, "step_late_" + method), "/state/actions/next_time", 0, 0.5);
    expect_refused("step_late_" + method, "the next fluid_step at t = 0.5 s");
    // Gas fields wild but not NaN: refused before the solver diverges on them.
    damage<double>(copy_of("steps_" + method, "gas_speed_" + method), "/gas/face_velocity_z", 2, 1e300);
    expect_refused("gas_speed_" + method, "/gas/face_velocity_z");
    damage<double>(copy_of("steps_" + method, "gas_porosity_" + method), "/gas/porosity", 1, 1.5);
    expect_refused("gas_porosity_" + method, "/gas/porosity");
    // A soft sphere's flight drive far beyond any terminal velocity: refused, not run until the
    // particle flies out of every grid (found by fuzz_resume).
    if (method == "soft_sphere") {
      damage<double>(copy_of("steps_" + method, "drive_" + method), "/state/particles/flight_drive", 4, 1e150);
      expect_refused("drive_" + method, "/state/particles/flight_drive");
    }
  }
}

TEST_F(DamagedCheckpoint, ASoftSphereDragRateWithoutGasIsRefused) {
  run_gas("soft_sphere", "run");
  for (const double rate : {1.6e69, -1.0}) {
    const std::string name = rate > 0 ? "huge_rate" : "negative_rate";
    damage<double>(copy_of("run", name), "/state/particles/flight_rate", 3, rate);
    expect_refused(name, "/state/particles/flight_rate");
  }
}

// Found by tests/fuzz/fuzz_resume: an inflow's entered count beyond every particle id made the
// next flow step owe a negative number of particles (cast to unsigned: undefined behaviour).
TEST_F(DamagedCheckpoint, AnInflowCountOutOfRangeIsRefused) {
  ASSERT_EQ(carom("run " + kScenes + "/duct_flow.toml --method soft_sphere --set time.end=0.05 --out duct --quiet"), 0)
      << out_;
  damage<std::uint64_t>(copy_of("duct", "entered"), "/flow/inflow_entered", 0, std::uint64_t{1} << 62);
  expect_refused("entered", "/flow/inflow_entered");
  damage<double>(copy_of("duct", "owed"), "/flow/inflow_owed", 0, 1e30);
  expect_refused("owed", "/flow/inflow_owed");
}

TEST_F(DamagedCheckpoint, ADamagedRunFileTimeIsRefused) {
  run_gas("event_driven", "run");
  copy_of("run", "bad_times");
  damage<double>((dir_ / "bad_times" / "run.h5").string(), "/timeseries/time", 3,
                 std::numeric_limits<double>::quiet_NaN(), false);
  expect_refused("bad_times", "/timeseries/time");
}

TEST_F(DamagedCheckpoint, TheCheckpointOfAnotherRunIsRefused) {
  run_gas("event_driven", "first");
  run_gas("event_driven", "second", " --seed 7");
  fs::copy_file(dir_ / "second" / "checkpoint.h5", dir_ / "first" / "checkpoint.h5",
                fs::copy_options::overwrite_existing);
  expect_refused("first", "different runs");
  // The same scene and seed run twice are two runs too: each run draws its own id.
  run_gas("event_driven", "third");
  fs::copy_file(dir_ / "third" / "checkpoint.h5", dir_ / "second" / "checkpoint.h5",
                fs::copy_options::overwrite_existing);
  expect_refused("second", "different runs");
}

TEST_F(DamagedCheckpoint, RunFileCheckpointAndSummaryShareOneIdentity) {
  run_gas("soft_sphere", "run");
  const carom::h5::File run = carom::h5::File::open((dir_ / "run" / "run.h5").string(), false);
  const carom::h5::File ckpt = carom::h5::File::open((dir_ / "run" / "checkpoint.h5").string(), false);
  const auto id = run.attribute<std::uint64_t>("run_id");
  EXPECT_NE(id, 0u);
  EXPECT_EQ(ckpt.attribute<std::uint64_t>("run_id"), id);
  EXPECT_EQ(ckpt.attribute<std::uint64_t>("scene_hash"), run.attribute<std::uint64_t>("scene_hash"));
  EXPECT_EQ(ckpt.attribute<std::string>("method"), "soft_sphere");
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(id));
  EXPECT_NE(read(dir_ / "run" / "summary.json").find("\"run\": {\"id\": \"" + std::string(hex) + "\""),
            std::string::npos)
      << read(dir_ / "run" / "summary.json");
}

}  // namespace
