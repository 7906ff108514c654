#pragma once
/// The gas of a scene wired into a simulator: the fluid step and, for kick flights, the drag
/// kicks as synchronising global events.
#include <memory>
#include <vector>

#include "events/method.hpp"
#include "fluid/coupling.hpp"
#include "fluid/kick_scheme.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

/// Builds the scene's gas and registers its global events with `sim` ("fluid_step" every
/// gas.time_step from the simulator's time; "drag_kick" every flight.particle_step for kick
/// flights). Returns nullptr when the scene has no coupled gas. `saved_state`: the gas state of
/// a checkpoint, restored so that a resumed run continues bit for bit.
std::unique_ptr<GasCoupling> attach_gas(CollisionMethod& sim, const Scene& scene,
                                        const h5::Group* saved_state = nullptr);

}  // namespace carom
