#pragma once
/// Reading the [[particles]] list of a scene: particles given one by one (SCENES.md).
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [[particles]] into scene.listed.
void read_listed(TableReader& root, Scene& scene);

}  // namespace carom
