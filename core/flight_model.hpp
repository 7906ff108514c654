#pragma once
/// How particles move between their interactions (core/DESIGN.md, "Particles and flights"): the one
/// choice of a run.
namespace carom {

enum class FlightModel {
  /// Gravity only: r(s) = r0 + v0 s + g s^2 / 2 (core/ballistic_flight.hpp).
  Ballistic,
  /// Exact ballistic-plus-drag: each particle flies its own RelaxFlight (gravity plus a linear
  /// drag frozen for one fluid step, core/relax_flight.hpp), set at every fluid step.
  Relax,
  /// The classic hard-sphere discrete-particle scheme: ballistic flights, and every particle
  /// step dt_p the drag and pressure-gradient impulses as explicit velocity kicks
  /// (fluid/kick_scheme.hpp). First order; unstable when dt_p > 2 tau.
  Kick,
};

}  // namespace carom
