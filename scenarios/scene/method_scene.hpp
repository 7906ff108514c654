#pragma once
/// Reading the [method] section of a scene (SCENES.md, "Method"): which collision method runs it.
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [method] into scene.method.kind (default "event_driven").
void read_method(TableReader& root, Scene& scene);

}  // namespace carom
