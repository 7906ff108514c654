#include "tests/fuzz/fuzz_check.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "scenarios/cli/check.hpp"
#include "scenarios/run/output_estimate.hpp"

namespace carom::fuzz {

void check_like_carom(Scene scene) {
  if (scene.from_file || scene.settle_time > 0.0) return;
  const std::size_t particles = planned_particle_count(scene);
  (void)estimate_output(scene, particles);
  if (particles > kMaxPlacedParticles) return;
  double smallest = std::numeric_limits<double>::infinity();
  for (const Species& species : scene.system.species)
    smallest = std::min(smallest, species.diameter);
  const Vec3 length = scene.system.domain.upper - scene.system.domain.lower;
  double cells = 1.0;
  for (int k = 0; k < 3; ++k) cells *= std::max(1.0, length[k] / smallest);
  if (!(cells <= kMaxGridCells)) return;
  build_initial_state(scene, nullptr);
  try {
    (void)make_method(scene.system, scene.method);  // main.cpp turns these into SceneError
  } catch (const std::invalid_argument&) {
    return;
  }
  (void)describe_scene(scene);
}

void expect_scene_errors_only(const std::function<void()>& body) {
  try {
    body();
  } catch (const SceneError&) {
    // the expected refusal of a bad input
  } catch (const std::exception& e) {
    std::fprintf(stderr, "carom fuzz: not a SceneError: %s\n", e.what());
    std::abort();
  }
}

}  // namespace carom::fuzz
