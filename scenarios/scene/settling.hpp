#pragma once
/// `[initial] settle_time`: the placed particles are run for a while (gravity, walls, contact
/// laws and collapse settings of the scene) and the end state becomes the initial state at t = 0.
#include "scenarios/scene/scene.hpp"

namespace carom {

/// Runs scene.system for scene.settle_time and replaces its particles by the state reached:
/// positions at the settled time (folded into the box on periodic axes), velocities and spins as
/// they are, or zero with settle_zero_velocity. Particle ids, species and their order are kept.
/// Throws SceneError when the settling collapses (with a hint to set collapse.contact_time).
void settle(Scene& scene);

}  // namespace carom
