#include "scenarios/scene/settling.hpp"

#include <algorithm>
#include <numeric>

#include "events/method_factory.hpp"

namespace carom {

void settle(Scene& scene, const volatile std::sig_atomic_t* stop) {
  System& system = scene.system;
  const std::string context = scene.settle_where + ": initial.settle_time = " + format_number(scene.settle_time);
  // Settling happens without the gas: ballistic flights, unless fixed particles sit under
  // gravity (they need each particle's own flight: relax flights without drag, which are the
  // same parabola, with a global step that only bounds the predictions).
  MethodSettings settings = scene.method;
  // A bed coming to rest needs excluded volume: the Monte Carlo method has none (its particles
  // would sink through each other onto the floor), so it settles event-driven.
  // initial.settle_method = "event_driven" asks for exact events whatever the method.
  if (settings.kind == MethodKind::MonteCarlo || scene.settle_by_events)
    settings.kind = MethodKind::EventDriven;
  const bool any_fixed = std::any_of(system.species.begin(), system.species.end(),
                                     [](const Species& s) { return s.fixed; });
  settings.event_driven.flight_model = any_fixed ? FlightModel::Relax : FlightModel::Ballistic;
  const std::unique_ptr<CollisionMethod> method = make_method(system, settings);
  CollisionMethod& sim = *method;
  if (any_fixed)
    sim.add_synchronising_action("settling_step", 0.0, std::max(scene.settle_time / 100.0, 1e-3),
                                 [](GlobalStep&) {});
  sim.set_stop_flag(stop);
  try {
    if (!sim.run_until(scene.settle_time))
      throw InterruptedBeforeStart("interrupted while settling (" + context + " s, stopped at " +
                                   format_number(sim.time()) +
                                   " s of it), before the run's t = 0: nothing was written; run the same "
                                   "command again to start over");
  } catch (const MethodFailure& e) {
    throw SceneError(context + ": the settling run failed: " + e.what());
  } catch (const InelasticCollapse& e) {
    const CollapseOptions& c = scene.method.event_driven.collapse;
    throw SceneError(
        context + ": the settling run collapsed: " + e.what() + " Hint: a bed coming to rest needs the TC model; " +
        (c.contact_time > 0.0
             ? "collisions.collapse.contact_time = " + format_number(c.contact_time) +
                   " s is too short for this bed, raise it (a tenth of the time a particle takes to fall "
                   "through its own radius is a fair start)"
             : std::string("set [collisions] collapse = { model = \"tc\", contact_time = 1e-5 } "
                           "(collisions.collapse.contact_time, s)")));
  }
  const ParticleStore& p = sim.system().particles;
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return p.id[a] < p.id[b]; });
  const Domain& d = system.domain;
  system.particles = ParticleStore{};
  for (std::size_t i : order) {
    Vec3 r = sim.position(i);
    for (int k = 0; k < 3; ++k) {  // a periodic image of the same state
      if (!d.periodic[k]) continue;
      if (r[k] >= d.upper[k]) r[k] -= d.upper[k] - d.lower[k];
      if (r[k] < d.lower[k]) r[k] += d.upper[k] - d.lower[k];
    }
    const bool zero = scene.settle_zero_velocity;
    system.add_particle(p.species[i], r, zero ? Vec3::Zero() : sim.velocity(i), zero ? Vec3::Zero() : sim.spin(i));
  }
}

}  // namespace carom
