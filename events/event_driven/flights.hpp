#pragma once
/// The flights of the event-driven engine: how a particle's stored state moves on between its
/// events. Each is a type with the same members, and the engine's hot paths are templates over
/// it, chosen once per run (EventDrivenEngine::run_until): no flight-model test in any of them.
/// Each flight's predictions (pairs, walls, cell crossings) are the engine's
/// predict<Flight> / predict_after_crossing<Flight>, in ballistic_predictions.cpp and
/// relax_predictions.cpp.
#include "core/ballistic_flight.hpp"
#include "core/relax_flight.hpp"
#include "events/event_driven/pair_batch.hpp"

namespace carom {

/// Ballistic flights without gravity: straight lines, r(s) = r0 + v0 s.
struct StraightFlights {
  static constexpr bool kGravity = false;
  static constexpr bool kGasForces = false;  ///< No gas force acts in flight.
  /// Moves state m on by dt (s).
  static void move(PairState& m, double dt, const BallisticFlight&, const RelaxFlight&) {
    m.position += dt * m.velocity;
  }
  /// Position dt (s) after m's clock, m.
  static Vec3 position_after(const PairState& m, double dt, const BallisticFlight& f, const RelaxFlight&) {
    return f.position(m.position, m.velocity, dt);
  }
  /// Velocity dt (s) after m's clock, m/s.
  static Vec3 velocity_after(const PairState& m, double dt, const BallisticFlight& f, const RelaxFlight&) {
    return f.velocity(m.velocity, dt);
  }
};

/// Ballistic flights under the system's gravity (one g for all: pairs move linearly relative to
/// each other, so pair contact is a quadratic).
struct GravityFlights {
  static constexpr bool kGravity = true;
  static constexpr bool kGasForces = false;
  static void move(PairState& m, double dt, const BallisticFlight& f, const RelaxFlight&) {
    m.position = f.position(m.position, m.velocity, dt);
    m.velocity = f.velocity(m.velocity, dt);
  }
  static Vec3 position_after(const PairState& m, double dt, const BallisticFlight& f, const RelaxFlight&) {
    return f.position(m.position, m.velocity, dt);
  }
  static Vec3 velocity_after(const PairState& m, double dt, const BallisticFlight& f, const RelaxFlight&) {
    return f.velocity(m.velocity, dt);
  }
};

/// Relax flights: each particle its own RelaxFlight (gravity plus a linear drag) until the next
/// synchronising action, beyond which nothing is predicted.
struct RelaxFlights {
  static constexpr bool kGravity = true;
  static constexpr bool kGasForces = true;  ///< The gas works on the particles in flight.
  static void move(PairState& m, double dt, const BallisticFlight&, const RelaxFlight& f) {
    m.position += f.displacement(m.velocity, dt);
    m.velocity = f.velocity(m.velocity, dt);
  }
  /// move(), bit for bit, returning the gas forces' work per unit mass on the way, J/kg.
  static double move_booking_gas_work(PairState& m, double dt, const BallisticFlight& b,
                                      const RelaxFlight& f) {
    return f.move_booking_gas_work(m.position, m.velocity, dt, b.gravity);
  }
  static Vec3 position_after(const PairState& m, double dt, const BallisticFlight&, const RelaxFlight& f) {
    return m.position + f.displacement(m.velocity, dt);
  }
  static Vec3 velocity_after(const PairState& m, double dt, const BallisticFlight&, const RelaxFlight& f) {
    return f.velocity(m.velocity, dt);
  }
};

}  // namespace carom
