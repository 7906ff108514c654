#pragma once
/// Tests: the event-driven engine's state inside a checkpoint read back.
#include "events/event_driven/engine_state.hpp"
#include "scenarios/run/run_output.hpp"

namespace carom {

/// The EngineState that a checkpoint of an event-driven run holds.
inline EngineState saved_engine_state(const Checkpoint& checkpoint) {
  return read_engine_state(checkpoint.method_state());
}

}  // namespace carom
