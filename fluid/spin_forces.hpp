#pragma once
/// Forces of the gas on a spinning sphere: the Magnus (slip-rotation) lift and the hydrodynamic
/// torque that slows the spin. Both depend on the relative rotation
///   Omega_rel = (1/2) curl u - omega,
/// the gas's local rotation less the particle's spin, rad/s. carom's gas cells span several
/// particle diameters, so the gas vorticity at the particle's scale is not resolved: carom takes
/// curl u = 0 and Omega_rel = -omega (the particle's own spin against gas in bulk translation).
/// Shear-induced (Saffman) lift is therefore not modelled either.
///
/// Sources, with their forms as cited by Crowe, Schwarzkopf, Sommerfeld & Tsuji, "Multiphase
/// flows with droplets and particles" (2nd ed. 2012, ch. 4) and Sommerfeld's ERCOFTAC best
/// practice guidelines:
///  - lift: Oesterle & Bui Dinh (1998), Exp. Fluids 25:16, measured for 10 < Re < 140 and spin
///    parameters 1 < Gamma < 6:
///      F_L = (pi/8) rho_g d^2 C_L |w| (Omega_rel x w) / |Omega_rel|,   w = u - v,
///      C_L = 0.45 + (2 Gamma - 0.45) exp(-0.075 Gamma^0.4 Re^0.7),
///      Gamma = d |Omega_rel| / (2 |w|),  Re = rho_g d |w| / mu_g (single sphere, no porosity).
///    (Written with Re_R = rho_g d^2 |Omega_rel| / mu_g = 2 Gamma Re it reads
///    C_L = 0.45 + (Re_R/Re - 0.45) exp(-0.05684 Re_R^0.4 Re^0.3), the form of Sommerfeld.)
///    As Gamma^0.4 Re^0.7 -> 0, C_L -> 2 Gamma and F_L -> pi rho_g a^3 Omega_rel x w, the
///    low-Re result of Rubinow & Keller (1961). Outside the measured range the formula is used
///    as it is (an extrapolation: say so when a scene goes there).
///  - torque: Dennis, Singh & Ingham (1980), J. Fluid Mech. 101:257, numerical solutions for a
///    sphere rotating in fluid at rest:
///      T = (rho_g / 2) (d/2)^5 C_R |Omega_rel| Omega_rel,   Re_R = rho_g d^2 |Omega_rel| / mu_g,
///      C_R = 64 pi / Re_R                          (Re_R <= 32: the Stokes rotlet T = 8 pi mu a^3
///      Omega), C_R = 12.9 / sqrt(Re_R) + 128.4 / Re_R      (32 < Re_R; fitted up to Re_R = 1000).
///    With Re_a = rho_g a^2 |Omega| / mu = Re_R / 4 (the variable of the form usually quoted
///    for Dennis et al.) the same fit reads C_R = 6.45 / sqrt(Re_a) + 32.1 / Re_a, and the
///    Stokes limit 16 pi / Re_a (not 64 pi / Re_a: 64 pi goes with Re_R). The two branches meet
///    within 0.2 % at Re_R = 32. Above Re_R = 1000 the fit is extrapolated. (The papers
///    themselves were not at hand: the forms and ranges are those of the citing texts, and the
///    limits, Stokes rotlet and Rubinow-Keller, are checked in tests/fluid/test_spin_forces.cpp.)
/// Sign: with Omega_rel = -omega (still gas) the torque opposes the spin, and backspin on a
/// sphere moving through still air lifts it (F_L along Omega_rel x (u - v)).
#include <array>
#include <string_view>

#include "core/vec3.hpp"

namespace carom {

/// Lift models a scene can select (`gas.magnus_lift`).
enum class MagnusLift {
  None,             ///< "none": no lift.
  OesterleBuiDinh,  ///< "oesterle_bui_dinh": Oesterle & Bui Dinh (1998), see the file comment.
};

/// Torque models a scene can select (`gas.rotational_torque`).
enum class RotationalTorque {
  None,    ///< "none": the spin changes only in collisions.
  Dennis,  ///< "dennis": Dennis, Singh & Ingham (1980) with its Stokes limit.
};

/// The scene names of the lift models, in MagnusLift order.
const std::array<std::string_view, 2>& magnus_lift_names();
/// The scene names of the torque models, in RotationalTorque order.
const std::array<std::string_view, 2>& rotational_torque_names();
/// The lift model called `name`; throws std::invalid_argument listing the allowed names.
MagnusLift parse_magnus_lift(std::string_view name);
/// The torque model called `name`; throws std::invalid_argument listing the allowed names.
RotationalTorque parse_rotational_torque(std::string_view name);

/// Which spin forces a run applies.
struct SpinForceSettings {
  MagnusLift lift = MagnusLift::None;                ///< Magnus lift model.
  RotationalTorque torque = RotationalTorque::None;  ///< Torque model.
  /// True when some spin force is on.
  bool any() const { return lift != MagnusLift::None || torque != RotationalTorque::None; }
};

/// What the spin forces need to know about one particle and the gas around it.
struct SpinForceInput {
  Vec3 slip = Vec3::Zero();               ///< u - v, gas minus particle velocity, m/s.
  Vec3 relative_rotation = Vec3::Zero();  ///< Omega_rel = (1/2) curl u - omega, rad/s.
  double diameter = 0.0;                  ///< d, m.
  double gas_density = 1.2;               ///< rho_g, kg/m^3.
  double gas_viscosity = 1.8e-5;          ///< mu_g, Pa s.
};

/// Spin parameter Gamma = d |Omega_rel| / (2 |u - v|), dimensionless (inf when |u - v| = 0).
double spin_parameter(const SpinForceInput& in);
/// Oesterle & Bui Dinh lift coefficient C_L(Gamma, Re) (file comment), dimensionless.
double oesterle_bui_dinh_lift_coefficient(double spin_parameter, double reynolds);
/// Magnus lift force F_L on the particle, N (zero when |u - v| = 0 or Omega_rel = 0).
Vec3 oesterle_bui_dinh_lift(const SpinForceInput& in);

/// Rotational Reynolds number Re_R = rho_g d^2 |Omega_rel| / mu_g, dimensionless.
double rotational_reynolds_number(const SpinForceInput& in);
/// Dennis, Singh & Ingham rotational coefficient C_R(Re_R) (file comment), dimensionless.
double dennis_rotational_coefficient(double rotational_reynolds);
/// Hydrodynamic torque T on the particle, N m (along Omega_rel).
Vec3 dennis_torque(const SpinForceInput& in);

/// The selected lift on one particle, N (zero for MagnusLift::None).
Vec3 magnus_lift_force(MagnusLift model, const SpinForceInput& in);
/// The selected torque on one particle, N m (zero for RotationalTorque::None).
Vec3 rotational_torque(RotationalTorque model, const SpinForceInput& in);

}  // namespace carom
