#pragma once
/// `carom check`: what a scene will model, and why, in plain words.
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "scenarios/cli/recommend.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

/// A report of a scene whose initial state has been built: box and walls, species and counts,
/// contact laws, whether rotation matters (not when every mu = 0), the collapse remedy, the gas
/// coupling (none yet), the grid levels, and Enskog's expected collision rate for a homogeneous
/// periodic gas.
std::string describe_scene(const Scene& scene);

/// The widest line `carom check` prints, characters.
inline constexpr std::size_t kCheckWidth = 100;

/// `text` with every line longer than `width` broken at spaces; a continued line is indented 4
/// more than the line it continues. A single word longer than the width (a long path) is left
/// whole on its own line.
std::string wrap_lines(const std::string& text, std::size_t width = kCheckWidth);

/// `carom check`: places the particles, checks what a run checks at its start, and writes the
/// report and the least model the scene needs to `out`. The scene's settling run
/// (initial.settle_time) is run only when `settle` is true; otherwise the estimates take the
/// bed as settled to a random packing (recommend.hpp, kSettledPacking), which keeps the check
/// to about a second where settling takes as long as that much simulation.
void check_scene(Scene scene, bool settle, std::ostream& out);

/// What `carom check` finds, as data (for the Python module's Scene.check).
struct CheckReport {
  std::string text;            ///< What check_scene writes, lines wrapped.
  SceneNumbers numbers;        ///< The estimates of the "least model" section.
  std::vector<Advice> advice;  ///< Its recommendations, the method first.
};

/// The work of check_scene, returned instead of written. Throws as check_scene does.
CheckReport check_report(Scene scene, bool settle);

}  // namespace carom
