#pragma once
/// Reading the [[inflow]], [[outflow]] and [flow] sections of a scene (particles entering
/// through inlet rectangles and leaving through outlet planes; events/flow/, SCENES.md).
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [[inflow]], [[outflow]] and [flow] into scene.flow (after [domain], [[species]],
/// [[walls]] and [gas]) and checks each inlet and outlet against the domain, the walls and the
/// species (check_inflow, check_outflow): a SceneError names the file, line, key and allowed
/// range.
void read_flow(TableReader& root, Scene& scene);

}  // namespace carom
