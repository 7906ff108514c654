#pragma once
/// Shared by the recommendation tests (test_recommend.cpp, test_recommend_charts.cpp).
#include <string>
#include <vector>

#include "scenarios/scene/scene.hpp"

namespace carom::test {

/// A shipped scene with overrides, its particles placed (no settling: the recommendation never
/// settles either).
inline Scene placed(const std::string& file, const std::vector<std::string>& overrides) {
  Scene scene = load_scene(std::string(CAROM_SCENES_DIR) + "/" + file, overrides);
  scene.settle_time = 0;
  build_initial_state(scene);
  return scene;
}

}  // namespace carom::test
