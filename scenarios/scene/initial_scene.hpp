#pragma once
/// Reading the [initial] section of a scene: seed, velocities, a file to start from, settling
/// (SCENES.md).
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [initial] into the scene's seed, temperature, from_file and settling settings.
void read_initial(TableReader& root, Scene& scene);

}  // namespace carom
