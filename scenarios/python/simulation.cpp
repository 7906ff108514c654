#include "scenarios/python/simulation.hpp"

#include <algorithm>
#include <numeric>
#include <random>

#include "scenarios/python/signal_guard.hpp"
#include "scenarios/run/checkpoint_check.hpp"
#include "scenarios/run/run_output.hpp"
#include "scenarios/scene/settling.hpp"

namespace carom::python {

Simulation::Simulation(Scene scene) : scene_(std::move(scene)) {
  {
    const SignalGuard signals;
    build_initial_state(scene_, stop_flag());
    if (*stop_flag())
      throw InterruptedBeforeStart("interrupted while the particles were placed: no simulation was made");
  }
  started_ = start_run(scene_);
  started_.method->set_stop_flag(stop_flag());
}

Simulation::Simulation(Scene scene, StartedRun started) : scene_(std::move(scene)), started_(std::move(started)) {
  started_.method->set_stop_flag(stop_flag());
}

Simulation Simulation::restore(const std::string& checkpoint_path) {
  Checkpoint checkpoint;
  try {
    checkpoint = read_checkpoint(checkpoint_path);
  } catch (const std::exception& e) {
    throw SceneError(std::string(e.what()) + " (cannot continue from it)");
  }
  Scene scene = parse_scene(checkpoint.info.scene_text, checkpoint_path + " (stored scene)");
  check_checkpoint_state(checkpoint, scene.system);
  StartedRun restored = restore_run(scene, checkpoint, checkpoint_path);
  return Simulation(std::move(scene), std::move(restored));
}

bool Simulation::advance(double t) {
  if (t <= time()) return true;
  const SignalGuard signals;
  return started_.method->run_until(t);
}

std::vector<std::size_t> Simulation::id_order() const {
  const ParticleStore& particles = started_.method->system().particles;
  std::vector<std::size_t> order(particles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return particles.id[a] < particles.id[b]; });
  return order;
}

void Simulation::checkpoint(const std::string& path) const {
  // A run id that identifies this checkpoint (as `carom run` draws one per run); no physics.
  std::random_device entropy;
  std::uint64_t run_id = 0;
  while (run_id == 0) run_id = (std::uint64_t(entropy()) << 32) ^ entropy();
  const RunInfo info{scene_.text, scene_.name, scene_.seed, std::string(method_name(scene_.method.kind)), run_id};
  write_checkpoint(path, *started_.method, info, started_.gas.get(), started_.flow.get());
}

}  // namespace carom::python
