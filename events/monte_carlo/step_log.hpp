#pragma once
/// What happened to one particle inside one Monte Carlo step: its wall impacts and collisions
/// with fictitious partners, in time order, each with the particle's state right after it.
///
/// A step is computed in full, from its start to its end, before the run reads anything inside
/// it; a run that stops inside a step (run_until's end, which is not a step boundary so that
/// where a run is cut never changes its dynamics) shows each particle as of its last logged
/// event (a delayed state, flown on to the current time), and the counters as they stood then.
#include <cstdint>

#include "core/vec3.hpp"

namespace carom {

struct StepEvent {
  double time = 0;                 ///< s (absolute).
  Vec3 position = Vec3::Zero();    ///< After the event, m.
  Vec3 velocity = Vec3::Zero();    ///< After the event, m/s.
  Vec3 spin = Vec3::Zero();        ///< After the event, rad/s.
  /// >= 0: a collision with a fictitious partner of this species; < 0: wall -1 - partner.
  std::int32_t partner = 0;
  Vec3 impulse = Vec3::Zero();     ///< On the particle, N s.
  Vec3 separation = Vec3::Zero();  ///< Pair: r_particle - r_partner = (R1 + R0) n, m.
  double dissipated = 0;           ///< Kinetic energy the particle lost (may be < 0 in a pair), J.
  /// Normal approach speed before the collision, m/s (for the impact count, System::is_impact).
  double approach = 0;
  /// Work of the gas forces (drag, pressure gradient) on the particle over its flight since its
  /// previous event or the step start, J (relax flights; 0 otherwise).
  double gas_work = 0;
};

}  // namespace carom
