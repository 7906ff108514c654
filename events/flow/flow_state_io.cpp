// The flow boundaries' state in HDF5 (checkpoints): written and read back exactly.
#include <string>
#include <vector>

#include "events/flow/flow_boundaries.hpp"

namespace carom {

// Layout (doubles as native doubles: bit for bit): attributes start_time, last_time, next_id,
// energy_in, energy_out; rng (the generator's text state); inflow_name, inflow_entered,
// inflow_owed, inflow_blocked_steps, inflow_failed_tries (one per inflow); outflow_name,
// outflow_left, outflow_left_mass (one per outflow); particle_seconds, present (one per
// species). Entered mass is entered times the particle mass and is not stored.
void FlowBoundaries::save(const h5::Group& group) const {
  group.set_attribute("start_time", start_time_);
  group.set_attribute("last_time", last_time_);
  group.set_attribute("next_id", next_id_);
  group.set_attribute("energy_in", energy_in_);
  group.set_attribute("energy_out", energy_out_);
  group.write_string("rng", rng_.state());

  std::vector<std::string> names;
  std::vector<std::uint64_t> entered, blocked, failed;
  std::vector<double> owed;
  for (std::size_t k = 0; k < inflows_.size(); ++k) {
    const InflowCounters& c = inflow_counters_[k];
    names.push_back(inflows_[k].name);
    entered.push_back(c.entered);
    owed.push_back(c.owed);
    blocked.push_back(c.blocked_steps);
    failed.push_back(c.failed_tries);
  }
  group.write_strings("inflow_name", names);
  group.write("inflow_entered", entered);
  group.write("inflow_owed", owed);
  group.write("inflow_blocked_steps", blocked);
  group.write("inflow_failed_tries", failed);

  names.clear();
  std::vector<std::uint64_t> left;
  std::vector<double> left_mass;
  for (std::size_t k = 0; k < outflows_.size(); ++k) {
    names.push_back(outflows_[k].name);
    left.push_back(outflow_counters_[k].left);
    left_mass.push_back(outflow_counters_[k].left_mass);
  }
  group.write_strings("outflow_name", names);
  group.write("outflow_left", left);
  group.write("outflow_left_mass", left_mass);

  group.write("particle_seconds", particle_seconds_);
  group.write("present", present_);
}

void FlowBoundaries::restore(const h5::Group& group) {
  const auto expect_names = [&](const std::string& dataset, const auto& flows,
                                const std::string& what) {
    std::vector<std::string> saved = group.read_strings(dataset);
    std::vector<std::string> names;
    for (const auto& f : flows) names.push_back(f.name);
    if (saved != names) {
      std::string list;
      for (const auto& s : saved) list += (list.empty() ? "\"" : ", \"") + s + "\"";
      group.fail("holds the state of the " + what + "s [" + list +
                 "], not those of the scene; resume with the scene the run was started with");
    }
  };
  expect_names("inflow_name", inflows_, "inflow");
  expect_names("outflow_name", outflows_, "outflow");
  const hsize_t inflows = inflows_.size(), outflows = outflows_.size();
  const hsize_t species = species_.size();
  const std::vector<std::uint64_t> entered = group.read<std::uint64_t>("inflow_entered", {inflows});
  const std::vector<double> owed = group.read<double>("inflow_owed", {inflows});
  const std::vector<std::uint64_t> blocked =
      group.read<std::uint64_t>("inflow_blocked_steps", {inflows});
  const std::vector<std::uint64_t> failed =
      group.read<std::uint64_t>("inflow_failed_tries", {inflows});
  const std::vector<std::uint64_t> left = group.read<std::uint64_t>("outflow_left", {outflows});
  const std::vector<double> left_mass = group.read<double>("outflow_left_mass", {outflows});
  // An empty dataset has shape {0}: read it without the shape check.
  std::vector<double> particle_seconds = group.read<double>("particle_seconds");
  std::vector<std::uint64_t> present = group.read<std::uint64_t>("present");
  if (particle_seconds.size() != species || present.size() != species)
    group.fail("holds particle-seconds of " + std::to_string(particle_seconds.size()) +
               " species; the scene has " + std::to_string(species));

  rng_.set_state(group.read_string("rng"));
  start_time_ = group.attribute<double>("start_time");
  last_time_ = group.attribute<double>("last_time");
  next_id_ = group.attribute<std::uint64_t>("next_id");
  energy_in_ = group.attribute<double>("energy_in");
  energy_out_ = group.attribute<double>("energy_out");
  for (std::size_t k = 0; k < inflows_.size(); ++k) {
    InflowCounters& c = inflow_counters_[k];
    c.entered = entered[k];
    c.entered_mass = static_cast<double>(c.entered) * species_[inflows_[k].species].mass();
    c.owed = owed[k];
    c.blocked_steps = blocked[k];
    c.failed_tries = failed[k];
  }
  for (std::size_t k = 0; k < outflows_.size(); ++k)
    outflow_counters_[k] = OutflowCounters{left[k], left_mass[k]};
  particle_seconds_ = std::move(particle_seconds);
  present_ = std::move(present);
}

}  // namespace carom
