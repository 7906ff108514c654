#pragma once
/// Reading the [[walls]] section of a scene (SCENES.md, "[[walls]]").
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Sets scene.system.walls to the box walls of the domain plus every [[walls]] entry (planes,
/// cylinders, cones), each checked against the domain and gravity read before.
void read_walls(TableReader& root, Scene& scene);

}  // namespace carom
