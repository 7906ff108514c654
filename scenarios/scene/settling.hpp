#pragma once
/// `[initial] settle_time`: the placed particles are run for a while (gravity, walls, contact
/// laws and collapse settings of the scene) and the end state becomes the initial state at t = 0.
#include <csignal>
#include <stdexcept>

#include "scenarios/scene/scene.hpp"

namespace carom {

/// A stop signal (SIGINT/SIGTERM) arrived before the run's t = 0, while the particles were
/// placed or settled: nothing was run and nothing written (exit code 130, run.hpp).
class InterruptedBeforeStart : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Runs scene.system for scene.settle_time (by the scene's method, or by exact events with
/// initial.settle_method = "event_driven") and replaces its particles by the state reached:
/// positions at the settled time (folded into the box on periodic axes), velocities and spins as
/// they are, or zero with settle_zero_velocity. Particle ids, species and their order are kept.
/// Throws SceneError when the settling collapses (with a hint to set collapse.contact_time), and
/// InterruptedBeforeStart when `stop` (a signal handler's flag; may be null) is raised first.
void settle(Scene& scene, const volatile std::sig_atomic_t* stop = nullptr);

}  // namespace carom
