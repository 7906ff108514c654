#pragma once
/// Reading the [method] section of a scene (which collision method runs it) and [engine] (the
/// event-driven engine's grid and checks); SCENES.md.
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [method] into scene.method.kind (default "event_driven").
void read_method(TableReader& root, Scene& scene);
/// Reads [engine] into scene.method.event_driven (grid levels, invariant checks).
void read_engine(TableReader& root, Scene& scene);

}  // namespace carom
