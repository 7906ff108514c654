#pragma once
/// Reading the [time] and [output] sections of a scene (SCENES.md).
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [time] (end) and [output] (snapshot, sample and checkpoint intervals).
void read_time_and_output(TableReader& root, Scene& scene);

}  // namespace carom
