#pragma once
/// Reading the [species.*] sections of a scene and their fills (SCENES.md).
#include <vector>

#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// Reads [species.*] into scene.system.species, keeping each table for read_fills.
void read_species(TableReader& root, Scene& scene, std::vector<TableReader>& species_tables);
/// Reads each species' fill (count, volume or mass fraction, region, arrangement) into scene.fills
/// (needs the regions read first).
void read_fills(Scene& scene, std::vector<TableReader>& species_tables);

}  // namespace carom
