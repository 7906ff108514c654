#pragma once
/// What `carom check` says about a soft-sphere scene: contact model, step, contact times and
/// overlaps at the expected impact speed.
#include <ostream>

#include "scenarios/scene/scene.hpp"

namespace carom {

/// Writes the soft-sphere lines of `carom check` (scene with its particles placed).
void describe_soft_sphere(const Scene& scene, std::ostream& out);

}  // namespace carom
