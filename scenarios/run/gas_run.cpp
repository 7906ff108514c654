#include "scenarios/run/gas_run.hpp"

namespace carom {

std::unique_ptr<GasCoupling> attach_gas(CollisionMethod& sim, const Scene& scene,
                                        const h5::Group* saved_state) {
  if (scene.gas.coupling == CouplingLevel::None) return nullptr;
  const System& system = sim.system();
  std::vector<double> density;
  for (const Species& s : system.species) density.push_back(s.density);
  auto gas = std::make_unique<GasCoupling>(scene.gas, system.domain, system.walls,
                                           system.flight.gravity, density);
  if (saved_state != nullptr)
    gas->restore(*saved_state);
  else
    gas->prepare(sim.system().particles);  // porosity at t = 0 for the first outputs
  GasCoupling* coupling = gas.get();
  const bool kick = scene.flight.model == FlightModel::Kick;
  // Kicks at least a fluid step apart see a drag refreshed at each: their stability is that of
  // explicit Euler on the nonlinear drag, limited by the longitudinal rate (kick_scheme.hpp).
  const bool refreshed = kick && scene.flight.particle_step >= scene.gas.time_step;
  coupling->keep_longitudinal_rates(refreshed);
  // Spin forces (gas.magnus_lift, gas.rotational_torque) are kicks too: the scene allows them
  // only with kick flights (scenarios/scene/gas_scene.cpp says why).
  const KickScheme kicks(scene.flight.particle_step, system.flight.gravity,
                         SpinForceKicks{scene.gas.spin_forces, scene.gas.density,
                                        scene.gas.viscosity});
  // The fluid step comes first in the calendar, so at a common time the kick uses the new drag.
  sim.add_synchronising_action("fluid_step", sim.time(), scene.gas.time_step,
                               [coupling, kick, refreshed, kicks](GlobalStep& step) {
                                 coupling->step(step.time, step.particles, step.flights, step.side);
                                 if (kick)
                                   kicks.check_stability(
                                       step.particles, step.flights,
                                       refreshed ? &coupling->longitudinal_rates() : nullptr);
                               });
  if (kick)
    sim.add_synchronising_action(
        "drag_kick", sim.time(), kicks.particle_step(),
        [kicks, coupling](GlobalStep& step) {
          kicks.kick(step.particles, step.flights, &coupling->gas_velocity_at_particles());
        });
  return gas;
}

}  // namespace carom
