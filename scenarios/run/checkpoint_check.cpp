#include "scenarios/run/checkpoint_check.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "scenarios/run/output_support.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

namespace {

std::string number(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

/// The error for dataset `path` of file `file`.
[[noreturn]] void refuse(const std::string& file, const std::string& path, const std::string& what) {
  throw SceneError(file + ": " + path + ": " + what +
                   ": the checkpoint is damaged or not carom's; resume from an intact copy or run the scene again");
}

/// Reads a whole dataset of group `group` as doubles (converted), with its path for messages.
std::vector<double> doubles(const h5::Group& group, const std::string& name) {
  return group.open_dataset(name).read<double>();
}

/// Every floating-point dataset and attribute under `group` (recursively) holds no NaN.
void check_no_nan(const h5::Group& group, const std::string& file) {
  for (const std::string& name : group.children()) {
    const std::string path = group.object_path() + (group.object_path() == "/" ? "" : "/") + name;
    H5O_info_t info;
    if (H5Oget_info_by_name2(group.id(), name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0)
      refuse(file, path, "cannot be read");
    if (info.type == H5O_TYPE_GROUP) {
      check_no_nan(group.open_group(name), file);
      continue;
    }
    if (info.type != H5O_TYPE_DATASET) continue;
    const h5::Dataset data = group.open_dataset(name);
    const hid_t type = H5Dget_type(data.id());
    const bool floating = H5Tget_class(type) == H5T_FLOAT;
    H5Tclose(type);
    if (!floating) continue;
    const std::vector<double> values = data.read<double>();
    for (std::size_t k = 0; k < values.size(); ++k)
      if (std::isnan(values[k])) refuse(file, path, "value " + std::to_string(k) + " is NaN");
  }
}

/// The gas state: every floating-point value finite, every gas velocity at most kMaxSpeed, every
/// porosity in [0, 1]. A wild but finite field would pass the NaN check and make the gas solver
/// diverge at its first step.
void check_gas(const std::string& file, const h5::Group& gas) {
  for (const std::string& name : gas.children()) {
    H5O_info_t info;
    if (H5Oget_info_by_name2(gas.id(), name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0 ||
        info.type != H5O_TYPE_DATASET)
      continue;
    const h5::Dataset data = gas.open_dataset(name);
    const hid_t type = H5Dget_type(data.id());
    const bool floating = H5Tget_class(type) == H5T_FLOAT;
    H5Tclose(type);
    if (!floating) continue;
    const std::string path = "/gas/" + name;
    const bool speed = name.starts_with("face_velocity_") || name.ends_with("gas_velocity");
    const bool porosity = name == "porosity" || name == "previous_porosity";
    const std::vector<double> values = data.read<double>();
    for (std::size_t k = 0; k < values.size(); ++k) {
      const double x = values[k];
      if (!std::isfinite(x)) refuse(file, path, "value " + std::to_string(k) + " is " + number(x) + ", not finite");
      if (speed && std::abs(x) > kMaxSpeed)
        refuse(file, path, "value " + std::to_string(k) + " is " + number(x) + " m/s, above the bound " + number(kMaxSpeed) + " m/s");
      if (porosity && !(x >= 0.0 && x <= 1.0))
        refuse(file, path, "value " + std::to_string(k) + " is " + number(x) + ", not a porosity in [0, 1]");
    }
  }
}

struct ParticleChecks {
  const std::string& file;
  const h5::Group& particles;
  std::string base;
  std::size_t n = 0;

  std::string path(const std::string& name) const { return base + "/" + name; }

  /// A 1-D dataset of n positive finite values.
  std::vector<double> positive(const std::string& name) const {
    const std::vector<double> values = doubles(particles, name);
    if (values.size() != n) refuse(file, path(name), "holds " + std::to_string(values.size()) + " values for " + std::to_string(n) + " particles");
    for (std::size_t i = 0; i < n; ++i)
      if (!(values[i] > 0 && std::isfinite(values[i])))
        refuse(file, path(name), "particle " + std::to_string(i) + " has " + number(values[i]) + ", not a positive finite number");
    return values;
  }
  /// An n x 3 dataset of finite values.
  std::vector<double> vectors(const std::string& name) const {
    const std::vector<double> values = doubles(particles, name);
    if (values.size() != 3 * n) refuse(file, path(name), "holds " + std::to_string(values.size()) + " values for " + std::to_string(n) + " particles x 3");
    for (std::size_t k = 0; k < values.size(); ++k)
      if (!std::isfinite(values[k]))
        refuse(file, path(name), "particle " + std::to_string(k / 3) + " has the non-finite component " + number(values[k]));
    return values;
  }
};

double norm3(const std::vector<double>& v, std::size_t i) {
  return std::sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
}

void check_events(const std::string& file, const h5::Group& state, const std::string& name, std::size_t n,
                  std::size_t walls, const std::vector<double>& clock) {
  if (!state.contains(name)) return;
  const h5::Group events = state.open_group(name);
  const std::string base = "/state/" + name;
  const std::vector<double> time = events.read<double>("time");
  const std::vector<std::int64_t> partner = events.read<std::int64_t>("partner");
  const std::vector<std::int64_t> kind = events.read<std::int64_t>("kind");
  if (time.size() != n || partner.size() != n || kind.size() != n)
    refuse(file, base, "does not hold one event per particle (" + std::to_string(n) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    // A particle's event is predicted from its clock: never before it.
    if (std::isnan(time[i]) || time[i] < 0 || (clock.size() == n && time[i] < clock[i]))
      refuse(file, base + "/time", "particle " + std::to_string(i) + "'s event time " + number(time[i]) +
                                       " s is NaN, negative or before the particle's clock");
    std::int64_t limit = 0;
    const char* what = "";
    switch (kind[i]) {
      case 0: continue;  // none
      case 1: limit = static_cast<std::int64_t>(n), what = "particle"; break;
      case 2: limit = static_cast<std::int64_t>(walls), what = "wall"; break;
      case 3: limit = 6, what = "cell face"; break;
      default: refuse(file, base + "/kind", "particle " + std::to_string(i) + "'s event kind " + std::to_string(kind[i]) + " is not one of 0-3");
    }
    if (partner[i] < 0 || partner[i] >= limit)
      refuse(file, base + "/partner", "particle " + std::to_string(i) + "'s " + what + " partner " + std::to_string(partner[i]) +
                                          " is outside 0.." + std::to_string(limit - 1));
  }
}

/// The inflow counters of /flow: every particle that entered took an id below next_id, so the
/// inflows' entered counts add up to at most next_id; the particles owed (due - entered, >= 0 by
/// construction) are finite and below 2^53. A count or debt out of range would give the next
/// flow step a negative or absurd number of particles to place.
void check_flow(const std::string& file, const h5::Group& flow) {
  if (!flow.contains("inflow_entered")) return;
  const std::uint64_t next_id = flow.has_attribute("next_id") ? flow.attribute<std::uint64_t>("next_id") : 0;
  const std::vector<std::uint64_t> entered = flow.read<std::uint64_t>("inflow_entered");
  std::uint64_t total = 0;
  for (const std::uint64_t count : entered) {
    total += count;
    if (count > next_id || total > next_id)
      refuse(file, "/flow/inflow_entered", "the inflows entered " + std::to_string(total) +
                                               " particles or more, beyond the next particle id " + std::to_string(next_id));
  }
  if (!flow.contains("inflow_owed")) return;
  const std::vector<double> owed = doubles(flow, "inflow_owed");
  for (std::size_t k = 0; k < owed.size(); ++k)
    if (!(std::isfinite(owed[k]) && owed[k] >= 0 && owed[k] < 9007199254740992.0))
      refuse(file, "/flow/inflow_owed", "inflow " + std::to_string(k) + " owes " + number(owed[k]) +
                                            " particles, not a count in [0, 2^53)");
}

}  // namespace

/// The checks of check_checkpoint_state; an HDF5 error (a dataset or attribute missing, a wrong
/// type) comes out as std::runtime_error, which check_checkpoint_state turns into a refusal.
static void check_state(const Checkpoint& checkpoint, const System& system) {
  const h5::File& f = *checkpoint.file;
  const std::string& file = f.file_path();
  const h5::Group state = checkpoint.method_state();
  if (!state.has_attribute("time")) refuse(file, "/state", "has no attribute time");
  const double now = state.attribute<double>("time");
  if (!(std::isfinite(now) && now >= 0)) refuse(file, "/state", "attribute time is " + number(now) + ", not a finite time >= 0");
  for (const char* group : {"state", "gas", "flow"})
    if (f.contains(group)) check_no_nan(f.open_group(group), file);
  if (f.contains("gas")) check_gas(file, f.open_group("gas"));

  if (!state.contains("particles")) refuse(file, "/state/particles", "is missing");
  const h5::Group particles = state.open_group("particles");
  const std::vector<hsize_t> shape = particles.open_dataset("position").shape();
  if (shape.size() != 2 || shape[1] != 3) refuse(file, "/state/particles/position", "must have shape {N, 3}");
  ParticleChecks c{file, particles, "/state/particles", static_cast<std::size_t>(shape[0])};
  const std::size_t n = c.n;
  const std::vector<double> radius = c.positive("radius");
  // Each particle's radius is its species' (as [initial] from_file requires): a wild radius would
  // pass the box test below with a margin as wild, and reach the grids' cell indices.
  if (particles.contains("species")) {
    const std::vector<std::int64_t> species = particles.read<std::int64_t>("species");
    if (species.size() != n) refuse(file, c.path("species"), "does not hold one value per particle");
    for (std::size_t i = 0; i < n; ++i) {
      if (species[i] < 0 || static_cast<std::size_t>(species[i]) >= system.species.size())
        refuse(file, c.path("species"), "particle " + std::to_string(i) + " has species index " + std::to_string(species[i]) +
                                            ", the scene has " + std::to_string(system.species.size()) + " species");
      const double expected = system.species[static_cast<std::size_t>(species[i])].radius();
      if (radius[i] != expected)
        refuse(file, c.path("radius"), "particle " + std::to_string(i) + " has radius " + number(radius[i]) + " m, its species' is " +
                                           number(expected) + " m");
    }
  } else {
    refuse(file, c.path("species"), "is missing");
  }
  c.positive("mass");
  c.positive("inertia");
  const std::vector<double> position = c.vectors("position");
  const std::vector<double> velocity = c.vectors("velocity");
  const std::vector<double> spin = c.vectors("spin");
  const double largest_radius = n > 0 ? *std::max_element(radius.begin(), radius.end()) : 0.0;
  const Domain& box = system.domain;
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      const double extent = box.upper[a] - box.lower[a];
      const double margin = box.periodic[a] ? extent : 2 * largest_radius + 1e-9 * extent;
      const double x = position[3 * i + a];
      if (x < box.lower[a] - margin || x > box.upper[a] + margin)
        refuse(file, c.path("position"), "particle " + std::to_string(i) + " is at " + "xyz"[a] + " = " + number(x) +
                                             " m, outside the box [" + number(box.lower[a]) + ", " + number(box.upper[a]) + "] m");
    }
    if (norm3(velocity, i) > kMaxSpeed)
      refuse(file, c.path("velocity"), "particle " + std::to_string(i) + " moves at " + number(norm3(velocity, i)) +
                                           " m/s, above the bound " + number(kMaxSpeed) + " m/s");
    if (norm3(spin, i) * radius[i] > kMaxSpeed)
      refuse(file, c.path("spin"), "particle " + std::to_string(i) + "'s surface moves at " + number(norm3(spin, i) * radius[i]) +
                                       " m/s, above the bound " + number(kMaxSpeed) + " m/s");
  }
  // Soft spheres: each particle's drag flight (rate 1/tau, 1/s). Without a gas there is no drag
  // (the flights are gravity alone, rate 0); with one a rate is finite and >= 0 (the engine
  // checks it against its step at each fluid step). A wild rate would make the velocities
  // explode within a step of the resumed run.
  if (particles.contains("flight_rate")) {
    const std::vector<double> rate = doubles(particles, "flight_rate");
    if (rate.size() != n) refuse(file, c.path("flight_rate"), "does not hold one value per particle");
    for (std::size_t i = 0; i < n; ++i)
      if (!(std::isfinite(rate[i]) && rate[i] >= 0 && (rate[i] == 0 || checkpoint.has_gas())))
        refuse(file, c.path("flight_rate"), "particle " + std::to_string(i) + "'s drag rate is " + number(rate[i]) +
                                                " 1/s, not " + (checkpoint.has_gas() ? "a finite rate >= 0" : "0 (the run has no gas)"));
  }
  // The drive of a flight (gravity, the gas's pressure gradient, and the drag's pull towards
  // the gas, rate u) over its rate is the flight's terminal velocity: it may not exceed
  // kMaxSpeed; without drag (rate 0) the drive may not bring a particle past kMaxSpeed within a
  // second. A wild drive would blow the resumed run up within a step and be misread as a
  // failing method.
  if (particles.contains("flight_drive")) {
    const std::vector<double> drive = c.vectors("flight_drive");
    const std::vector<double> rate =
        particles.contains("flight_rate") ? doubles(particles, "flight_rate") : std::vector<double>(n, 0.0);
    for (std::size_t i = 0; i < n && i < rate.size(); ++i)
      if (norm3(drive, i) > kMaxSpeed * (1.0 + rate[i]))
        refuse(file, c.path("flight_drive"), "particle " + std::to_string(i) + "'s drive is " + number(norm3(drive, i)) +
                                                 " m/s^2, above the bound " + number(kMaxSpeed * (1.0 + rate[i])) +
                                                 " m/s^2 (" + number(kMaxSpeed) + " m/s times 1/s plus its drag rate)");
  }
  std::vector<double> clock;
  if (particles.contains("clock")) {
    clock = doubles(particles, "clock");
    if (clock.size() != n) refuse(file, c.path("clock"), "does not hold one value per particle");
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(clock[i]) || clock[i] > now)
        refuse(file, c.path("clock"), "particle " + std::to_string(i) + "'s clock is " + number(clock[i]) +
                                          " s, not a finite time at or before the state's time " + number(now) + " s");
  }
  if (particles.contains("id")) {
    const std::vector<std::uint64_t> id = particles.read<std::uint64_t>("id");
    if (id.size() != n) refuse(file, c.path("id"), "does not hold one value per particle");
    std::unordered_set<std::uint64_t> seen;
    for (std::size_t i = 0; i < n; ++i)
      if (!seen.insert(id[i]).second) refuse(file, c.path("id"), "id " + std::to_string(id[i]) + " is held by two particles");
  }
  check_events(file, state, "events", n, system.walls.size(), clock);
  check_events(file, state, "crossings", n, system.walls.size(), clock);
  if (f.contains("flow")) check_flow(file, f.open_group("flow"));
}

void check_checkpoint_state(const Checkpoint& checkpoint, const System& system) {
  try {
    check_state(checkpoint, system);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {  // e.g. "checkpoint.h5:/state/particles: has no dataset 'mass'"
    throw SceneError(std::string(e.what()) +
                     ": the checkpoint is damaged or not carom's; resume from an intact copy or run the scene again");
  }
}

void check_restored_state(const CollisionMethod& sim, MethodKind kind, const std::string& checkpoint_path) {
  if (kind != MethodKind::EventDriven) return;  // soft spheres overlap by design; Monte Carlo partners are fictitious
  System now = sim.system();
  for (std::size_t i = 0; i < now.particles.size(); ++i) now.particles.position[i] = sim.position(i);
  try {
    validate_initial_state(now, kContactTolerance);
  } catch (const std::invalid_argument& e) {
    refuse(checkpoint_path, "/state/particles/position", std::string("at t = ") + number(sim.time()) + " s: " + e.what());
  }
}

void check_run_file_matches(const std::string& run_path, const Checkpoint& checkpoint) {
  RunInfo run;
  try {
    const h5::File f = h5::File::open(run_path, false);
    run = output_detail::read_info(f, output_detail::kRunKind);
    if (f.contains("timeseries") && f.open_group("timeseries").contains("time")) {
      const std::vector<double> time = f.open_group("timeseries").read<double>("time");
      for (std::size_t k = 0; k < time.size(); ++k)
        if (!std::isfinite(time[k]) || time[k] < 0 || (k > 0 && time[k] < time[k - 1]))
          refuse(run_path, "/timeseries/time", "row " + std::to_string(k) + " is " + number(time[k]) +
                                                   " s: the times are not finite and ordered");
    }
    if (f.contains("snapshots")) {
      const h5::Group snapshots = f.open_group("snapshots");
      double previous = -1;
      for (const std::string& name : snapshots.children()) {
        const double t = snapshots.open_group(name).attribute<double>("time");
        if (!std::isfinite(t) || t < previous)
          refuse(run_path, "/snapshots/" + name, "its time " + number(t) + " s is not finite and after the previous snapshot's");
        previous = t;
      }
    }
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(std::string(e.what()) + ": `carom resume` needs the run file the checkpoint continues");
  }
  const RunInfo& saved = checkpoint.info;
  const std::string both = run_path + " and " + checkpoint.file->file_path();
  // The scene text may differ (`carom resume --end` stores the new end time in the checkpoint);
  // the run id is drawn once per run. Files from before run ids (0) are compared by name.
  if (run.run_id != saved.run_id || run.seed != saved.seed || run.method != saved.method ||
      (run.run_id == 0 && run.scene_name != saved.scene_name))
    throw SceneError(both + " belong to different runs (run id " + std::to_string(run.run_id) + " against " +
                     std::to_string(saved.run_id) + ", seed " + std::to_string(run.seed) + " against " +
                     std::to_string(saved.seed) + ", method '" + run.method.substr(0, 64) + "' against '" +
                     saved.method.substr(0, 64) + "', scene '" + run.scene_name.substr(0, 64) + "' against '" +
                     saved.scene_name.substr(0, 64) + "'); resume needs the run file and checkpoint of one run");
}

}  // namespace carom
