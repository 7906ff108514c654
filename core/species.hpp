#pragma once
/// A species: one kind of solid sphere (size and material density).
#include <numbers>
#include <string>

namespace carom {

struct Species {
  std::string name;      ///< Label used in scenes and outputs.
  double diameter = 0;   ///< Sphere diameter d, m.
  double density = 0;    ///< Solid density rho_p, kg/m^3.
  /// Fixed particles never move: obstacles, the packing of a fixed bed. They collide as bodies
  /// of infinite mass and feel no force (the gas still feels their drag).
  bool fixed = false;

  /// Radius a = d/2, m.
  double radius() const { return 0.5 * diameter; }
  /// Volume pi d^3 / 6, m^3.
  double volume() const { return std::numbers::pi / 6.0 * diameter * diameter * diameter; }
  /// Mass m = rho_p V, kg.
  double mass() const { return density * volume(); }
  /// Moment of inertia of a solid sphere, (2/5) m a^2, kg m^2.
  double inertia() const { return 0.4 * mass() * radius() * radius(); }
};

}  // namespace carom
