#pragma once
/// `carom check`: what a scene will model, and why, in plain words.
#include <string>

#include "scenarios/scene/scene.hpp"

namespace carom {

/// A report of a scene whose initial state has been built: box and walls, species and counts,
/// contact laws, whether rotation matters (not when every mu = 0), the collapse remedy, the gas
/// coupling (none yet), the grid levels, and Enskog's expected collision rate for a homogeneous
/// periodic gas.
std::string describe_scene(const Scene& scene);

}  // namespace carom
