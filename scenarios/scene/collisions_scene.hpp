#pragma once
/// Reading the [collisions] section of a scene: the contact laws per species pair and per
/// species-wall pair, and the collapse remedies (SCENES.md).
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [collisions] into scene.system.materials and scene.method.event_driven.collapse (needs
/// the species and walls read first).
void read_collisions(TableReader& root, Scene& scene);

}  // namespace carom
