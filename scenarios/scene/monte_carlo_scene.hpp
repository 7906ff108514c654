#pragma once
/// Reading the [monte_carlo] section of a scene (the Monte Carlo method's step, cells, collision
/// frequency, contact value and seed); SCENES.md.
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [monte_carlo] into scene.method.monte_carlo, and gives it the scene's flight model
/// (after [flight] and [gas]) and, unless the section names its own, initial.seed. Read
/// whatever [method] kind says (used only by "monte_carlo"), so that one scene can be swept
/// over methods.
void read_monte_carlo(TableReader& root, Scene& scene);

}  // namespace carom
