#pragma once
/// Reading the [domain] and [regions] sections of a scene (SCENES.md).
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [domain] (box, periodic axes, gravity) into scene.system.
void read_domain(TableReader& root, Scene& scene);
/// Reads [regions.*] into scene.regions (regions[0] is the whole domain, "domain").
void read_regions(TableReader& root, Scene& scene);

}  // namespace carom
