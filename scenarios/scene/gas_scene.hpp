#pragma once
/// Reading the [flight] and [gas] sections of a scene (SCENES.md, "Gas and flights").
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [flight] and [gas] into scene.flight and scene.gas and checks that they fit together
/// (relax and kick flights need a coupled gas; a coupled gas needs relax or kick flights).
void read_flight_and_gas(TableReader& root, Scene& scene);

}  // namespace carom
