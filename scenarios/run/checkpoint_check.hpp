#pragma once
/// What a checkpoint and the run file it continues must satisfy before `carom resume` rebuilds
/// a method from them: every index in range, every count consistent, every physical quantity
/// finite and meaningful. A failure is a SceneError (exit 2) that names the file, the dataset
/// and what is wrong, so a damaged state is refused instead of crashing or resuming to a wrong
/// result. These checks add to the checksum (file_checksum.hpp), which catches damage to any
/// stored value but not a file written wrongly and sealed.
#include <string>

#include "core/system.hpp"
#include "events/method.hpp"
#include "events/method_factory.hpp"
#include "scenarios/run/run_output.hpp"
#include "scenarios/scene/state_bounds.hpp"

namespace carom {

/// Checks the method's state in `checkpoint` against `system` (the scene's box, species and
/// walls): time finite and >= 0; per particle position finite and inside the box (periodic
/// axes: within one box length of it; walled axes: within two largest radii), velocity finite
/// and at most kMaxSpeed, spin finite with |spin| r at most kMaxSpeed, radius, mass and inertia
/// positive and finite, clock finite and not after the time, species index below the species
/// count, ids unique; for the event-driven engine each event's and crossing's partner in range
/// of its kind (particle, wall, face), its time not NaN and not before the particle's clock; no
/// floating-point value anywhere in /state, /gas or /flow NaN; in /gas every value finite, gas
/// velocities at most kMaxSpeed and porosities in [0, 1]. Throws SceneError.
void check_checkpoint_state(const Checkpoint& checkpoint, const System& system);

/// Checks the state a method was rebuilt into from the checkpoint at `checkpoint_path`, at its
/// current time: for hard spheres (the event-driven method), no two particles overlap and none
/// pokes through a wall beyond kContactTolerance (the engine's own invariant, which the
/// per-value checks above cannot see). Throws SceneError.
void check_restored_state(const CollisionMethod& sim, MethodKind kind, const std::string& checkpoint_path);

/// Checks that the run file at `run_path` belongs to the run of `checkpoint` (same run id, seed
/// and method) and that its time series and snapshot times are finite and ordered. Throws
/// SceneError.
void check_run_file_matches(const std::string& run_path, const Checkpoint& checkpoint);

}  // namespace carom
