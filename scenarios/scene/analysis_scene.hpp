#pragma once
/// Reading the [analysis] section of a scene (SCENES.md, "Analysis").
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [analysis] into scene.analysis (needs species, regions and the domain read first).
void read_analysis(TableReader& root, Scene& scene);

}  // namespace carom
