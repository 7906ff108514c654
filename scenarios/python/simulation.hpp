#pragma once
/// A scene stepped in process: the Python module's Simulation. It is the method, flow and gas
/// that `carom run` steps (run.hpp, start_run), advanced by the same run_until calls, without
/// the run loop's outputs: the caller reads the state between steps.
#include <cstddef>
#include <string>
#include <vector>

#include "scenarios/run/run.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom::python {

class Simulation {
 public:
  /// Places the particles (and settles them, with initial.settle_time) and starts the method at
  /// t = 0. Throws SceneError, or InterruptedBeforeStart when a stop signal came first.
  explicit Simulation(Scene scene);
  /// Continues from a checkpoint (of `carom run` or of checkpoint() below) with the scene stored
  /// in it, as `carom resume` does: bit for bit. Throws SceneError for a checkpoint that is
  /// missing, damaged or not one carom can continue.
  static Simulation restore(const std::string& checkpoint_path);

  /// Runs to time t, s (t at or before the current time: nothing to do). Returns false when a
  /// stop signal (Ctrl-C) came first: the state is then a consistent one short of t.
  /// As `carom run` at an output instant, the method stops exactly at t. The event-driven
  /// method's stop touches no particle and Monte Carlo shows its particles part way through a
  /// step it finishes later, so any t leaves their runs unchanged; soft spheres cut their last
  /// step to land on t, unless t is a step boundary (stop_time). Throws the method's failures
  /// (InelasticCollapse, MethodFailure, ...).
  bool advance(double t);
  /// The earliest time >= t at which the method stops without changing the run: t for the
  /// event-driven and Monte Carlo methods, the next step boundary or synchronising action for
  /// soft spheres.
  double stop_time(double t) const { return started_.method->stop_time(t); }
  /// The current time, s.
  double time() const { return started_.method->time(); }

  const Scene& scene() const { return scene_; }
  const CollisionMethod& method() const { return *started_.method; }
  /// The gas (null without a coupled gas) and the inflows and outflows (null without them).
  const GasCoupling* gas() const { return started_.gas.get(); }
  const FlowBoundaries* flow() const { return started_.flow.get(); }
  /// The method's particle indices in the order of the particle ids: the rows of the run file's
  /// snapshots, so that row k is the same particle at every step.
  std::vector<std::size_t> id_order() const;
  /// Writes a checkpoint of the current state (run_output.hpp): the particles of `[initial]
  /// from_file`, and a state Simulation::restore continues bit for bit.
  void checkpoint(const std::string& path) const;

 private:
  Simulation(Scene scene, StartedRun started);
  Scene scene_;
  StartedRun started_;
};

}  // namespace carom::python
