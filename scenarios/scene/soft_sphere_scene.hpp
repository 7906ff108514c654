#pragma once
/// Reading the [soft_sphere] section (contact model, step, skin, detectors) and checking that
/// a soft-sphere scene has what the method needs (elastic constants); SCENES.md.
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [soft_sphere] into scene.method.soft_sphere; call after read_method and the gas.
void read_soft_sphere(TableReader& root, Scene& scene);

}  // namespace carom
