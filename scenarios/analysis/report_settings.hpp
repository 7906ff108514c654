#pragma once
/// The section of report.md that says which numerical settings a run's numbers depend on (the TC
/// time, the stiffness and step, the Monte Carlo step and cells, the gas grid and step, the seed)
/// and, where a shipped chart measured it, how much they moved with them, so that no number in a
/// report stands without what it depends on.
#include <string>

#include "scenarios/scene/scene.hpp"

namespace carom {

/// The markdown section "What these numbers depend on" for a run of `scene`.
std::string numerical_settings_section(const Scene& scene);

}  // namespace carom
