#pragma once
/// Tests: the event-driven engine's state inside a checkpoint read back.
#include <map>
#include <string>
#include <vector>

#include "events/event_driven/engine_state.hpp"
#include "scenarios/run/run_output.hpp"

namespace carom {

/// The EngineState that a checkpoint of an event-driven run holds.
inline EngineState saved_engine_state(const Checkpoint& checkpoint) {
  return read_engine_state(checkpoint.method_state());
}

/// Every array of a checkpoint's gas state by name, as doubles, except the wall times (which no
/// two runs share).
inline std::map<std::string, std::vector<double>> saved_gas_arrays(const Checkpoint& checkpoint) {
  std::map<std::string, std::vector<double>> arrays;
  const h5::Group gas = checkpoint.gas_state();
  for (const std::string& name : gas.children())
    if (name != "wall_seconds") arrays[name] = gas.open_dataset(name).read<double>();
  return arrays;
}

}  // namespace carom
