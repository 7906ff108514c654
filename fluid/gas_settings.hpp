#pragma once
/// What a scene says about the gas: its properties, grid, boundaries, drag closure, time step
/// and how strongly it is coupled to the particles. Plain data; GasCoupling turns it into a
/// solver. SCENES.md documents the scene keys that fill it.
#include <array>
#include <string>
#include <vector>

#include "drag.hpp"
#include "spin_forces.hpp"

namespace carom {

/// How the gas and the particles act on each other (core/DESIGN.md, "The gas and the two time
/// scales").
enum class CouplingLevel {
  None,    ///< No gas: granular gases, clouds in vacuum.
  OneWay,  ///< The gas moves the particles; the particles neither displace nor push the gas.
  TwoWay,  ///< Both: porosity in the gas equations and the drag reaction on the gas.
};

/// A jet: part of an inlet face with its own superficial velocity.
struct InletJet {
  std::array<double, 2>
      lower{};  ///< Lower corner on the face (the two other axes in x, y, z order), m.
  std::array<double, 2> upper{};  ///< Upper corner, m.
  double velocity = 0;            ///< Superficial velocity into the domain, m/s.
};

/// The gas boundary on one side of the box.
struct GasSide {
  enum class Kind { Wall, FreeSlip, Inlet, Outlet, Periodic };
  Kind kind = Kind::FreeSlip;
  double velocity = 0;  ///< Inlet: superficial velocity into the domain, m/s.
  double ramp_time =
      0;  ///< Inlet: the velocity rises linearly from 0 over this time, s (0: at once).
  std::vector<InletJet> jets;  ///< Inlet: faces inside a jet blow at the jet's velocity instead.
  double pressure = 0;         ///< Outlet: pressure, Pa.
};

struct GasSettings {
  CouplingLevel coupling = CouplingLevel::None;
  double density = 1.2;                                      ///< rho_g, kg/m^3.
  double viscosity = 1.8e-5;                                 ///< mu_g, Pa s.
  std::array<int, 3> cells{1, 1, 1};                         ///< Gas cells per axis.
  double time_step = 1e-4;                                   ///< Fluid step dt, s.
  DragClosureKind closure = DragClosureKind::GidaspowBlend;  ///< Drag closure (fluid/drag.hpp).
  double fluidization_porosity =
      0.4;                       ///< eps_mf of the Richardson-Zaki exponent (schiller_naumann).
  double min_porosity = 0.2;     ///< Porosity floor of the mapping (round-off in packed cells).
  std::array<GasSide, 6> sides;  ///< x_low, x_high, y_low, y_high, z_low, z_high.
  SpinForceSettings spin_forces;  ///< Magnus lift and rotational torque (kick flights only).
};

/// The names of the six sides, in GasSettings::sides order.
inline const std::array<std::string, 6>& gas_side_names() {
  static const std::array<std::string, 6> names{"x_low",  "x_high", "y_low",
                                                "y_high", "z_low",  "z_high"};
  return names;
}

}  // namespace carom
