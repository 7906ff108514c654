#pragma once
/// Gas-particle drag closures (core/DESIGN.md, "The gas and the two time scales"): the drag
/// coefficient K of one particle.
///
/// Conventions (the model of core/DESIGN.md, "The gas and the two time scales": the gas feels -eps
/// grad p and -beta (u - v) per unit volume; a particle feels m g - V_p grad p + K (u - v)):
///  - u is the interstitial gas velocity, v the particle velocity, slip = |u - v|, m/s;
///  - Re = eps rho_g d |u - v| / mu_g (the superficial slip eps |u - v| times d / nu);
///  - K, kg/s: the drag force on one particle is F = K (u - v); its relaxation time is m / K;
///  - beta, kg/(m^3 s): momentum exchange per unit mixture volume, beta = K (1 - eps) / V_p, so
///    that F = beta V_p / (1 - eps) (u - v). K is the primary quantity: it stays finite for a
///    single sphere (eps -> 1) where beta -> 0.
/// The drag here is the "model A" drag of Gidaspow, Ergun, Wen-Yu and Di Felice: it excludes the
/// -V_p grad p share of the fluid force. In a homogeneous bed at rest the gas pressure gradient
/// carries the rest, and the force balance per particle reads K u = eps V_p (rho_p - rho_g) g
/// (derivation at minimum_fluidization_velocity below).
#include <array>
#include <string>
#include <string_view>

namespace carom {

/// The drag closures a scene can select (`gas.closure`).
enum class DragClosureKind {
  SchillerNaumann,  ///< "schiller_naumann": single sphere + Richardson-Zaki eps^-n (see below).
  Ergun,            ///< "ergun": Ergun (1952) at every porosity.
  WenYu,            ///< "wen_yu": Wen & Yu (1966).
  Gidaspow,         ///< "gidaspow": Ergun for eps < 0.8, Wen-Yu above (Ding & Gidaspow 1990).
  GidaspowBlend,    ///< "gidaspow_blend": arctan blend of the two (Lathouwers & Bellan 2000).
  Beetstra,         ///< "beetstra": Beetstra, van der Hoef & Kuipers (2007), polydisperse.
  DiFelice,         ///< "di_felice": Di Felice (1994) voidage function eps^-chi(Re).
  MorsiAlexander,   ///< "morsi_alexander": single sphere, no porosity (fluid/morsi_alexander.hpp).
};

/// The scene names of the closures, in DragClosureKind order.
const std::array<std::string_view, 8>& drag_closure_names();
/// The scene name of a closure.
std::string_view drag_closure_name(DragClosureKind kind);
/// The closure called `name`; throws std::invalid_argument listing the allowed names.
DragClosureKind parse_drag_closure(std::string_view name);

/// What a closure needs to know about one particle and the gas around it.
struct DragInput {
  double porosity = 1.0;            ///< Local gas volume fraction eps (0 < eps <= 1).
  double slip = 0.0;                ///< |u - v|, interstitial gas minus particle velocity, m/s.
  double diameter = 0.0;            ///< Particle diameter d_i, m.
  double sauter_diameter = 0.0;     ///< Local Sauter mean diameter <d> (beetstra), m; 0: d_i.
  double gas_density = 1.2;         ///< rho_g, kg/m^3.
  double gas_viscosity = 1.8e-5;    ///< mu_g, Pa s.
  double particle_density = 2500.;  ///< rho_p (schiller_naumann's exponent n), kg/m^3.
};

/// Particle Reynolds number Re = eps rho_g d |u - v| / mu_g (d = in.diameter), dimensionless.
double reynolds_number(const DragInput& in);
/// Particle volume V_p = pi d^3 / 6, m^3.
double particle_volume(double diameter);

// --- Single-sphere drag -------------------------------------------------------------------

/// Schiller-Naumann C_d Re / 24 = 1 + 0.15 Re^0.687 (Re < 1000), 0.44 Re / 24 above; the
/// single-sphere drag is 3 pi mu d U times this (Re built with U), dimensionless.
double schiller_naumann_factor(double reynolds);
/// Schiller-Naumann drag coefficient C_d(Re), dimensionless.
double schiller_naumann_cd(double reynolds);

// --- The closures: K of one particle, kg/s ------------------------------------------------

/// Schiller-Naumann with the Richardson-Zaki porosity function f = eps^-n:
///   F = eps F_SN(f U_s), U_s = eps |u - v| (superficial slip), F_SN(U) = C_d(Re_U) pi d^2/8 rho_g
///   U^2,
/// i.e. f scales the slip (and Re) seen by the single-sphere law, and the prefactor eps is the
/// share of the buoyant weight the drag carries in this model. In K form:
///   K = 3 pi mu d eps^(2 - n) (C_d Re_f / 24)(Re_f),  Re_f = eps^-n Re.
/// A bed at porosity eps then balances its weight (K u = eps V_p (rho_p - rho_g) g) exactly at
/// U = U_t eps^n (Richardson-Zaki), for every eps; eps = 1 is plain Schiller-Naumann.
double schiller_naumann_drag(const DragInput& in, double exponent_n);
/// Ergun: beta = 150 (1 - eps)^2 mu / (eps d^2) + 1.75 (1 - eps) rho_g |u - v| / d, so
/// K = V_p [150 (1 - eps) mu / (eps d^2) + 1.75 rho_g |u - v| / d].
double ergun_drag(const DragInput& in);
/// Wen-Yu: beta = 3/4 C_d eps (1 - eps) rho_g |u - v| / d eps^-2.65 (C_d Schiller-Naumann at Re),
/// K = 3 pi mu d eps^-2.65 (C_d Re / 24).
double wen_yu_drag(const DragInput& in);
/// Gidaspow: Ergun for eps < 0.8, Wen-Yu for eps >= 0.8 (discontinuous at 0.8).
double gidaspow_drag(const DragInput& in);
/// Weight phi of Wen-Yu in the Gidaspow blend: 1/2 + arctan(262.5 (eps - 0.8)) / pi.
double gidaspow_blend_weight(double porosity);
/// Gidaspow blend: K = (1 - phi) K_Ergun + phi K_WenYu (Huilin & Gidaspow 2003 switch).
double gidaspow_blend_drag(const DragInput& in);
/// Beetstra, van der Hoef & Kuipers (2007) monodisperse F(phi, Re) = F_d / (3 pi mu d U),
/// U = eps |u - v| superficial, phi = 1 - eps, Re with U (AIChE J. 53:489, eq. 16 as cited by
/// CFDEMcoupling; same form in OpenFOAM and MFiX, which use beta = 18 mu eps phi F / d^2, i.e.
/// K = 3 pi mu d eps F), dimensionless:
///   F = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi)) + 0.413 Re/(24 eps^2)
///       (1/eps + 3 phi eps + 8.4 Re^-0.343) / (1 + 10^(3 phi) Re^(-(1 + 4 phi)/2)).
double beetstra_monodisperse_f(double solid_fraction, double reynolds);
/// Beetstra with the polydisperse correction: y = d_i / <d>, Re built with <d>,
///   K_i = 3 pi mu d_i eps y F(phi, Re_<d>).
/// y F is the model-A form of the van der Hoef (2005) / Beetstra (2007) total-force correction
/// F_i / F = eps y + phi y^2 (see drag.cpp); a bed's total drag is that of a monodisperse bed of
/// Sauter diameter exactly, and y = 1 is the monodisperse closure.
double beetstra_drag(const DragInput& in);
/// Di Felice exponent chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2), dimensionless.
double di_felice_exponent(double reynolds);
/// Di Felice: F = C_d pi d^2/8 rho_g eps^2 |u - v| (u - v) eps^-chi, C_d = (0.63 + 4.8/sqrt(Re))^2,
/// i.e. the single-sphere drag at the superficial slip times eps^-chi; in K form
/// K = 3 pi mu d eps^(1 - chi) (0.63 sqrt(Re) + 4.8)^2 / 24. This F is the model-A drag: the
/// balance K u = eps W gives U ~ eps^(1 + chi) (n = 4.7) at low Re and eps^((1 + chi)/2)
/// (n = 2.39) at high Re, Richardson-Zaki's limits (Di Felice's argument: the drag carries the
/// weight less the buoyancy in the suspension, eps W).
double di_felice_drag(const DragInput& in);

// --- Settling, fluidization and the Richardson-Zaki exponent --------------------------------

/// Archimedes number Ar = d^3 rho_g (rho_p - rho_g) g / mu_g^2 (in: diameter, densities,
/// viscosity), dimensionless.
double archimedes_number(const DragInput& in, double gravity);
/// Wen-Yu correlation: Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7, dimensionless.
double wen_yu_minimum_fluidization_reynolds(double archimedes);
/// Wen-Yu correlation U_mf = Re_mf mu_g / (rho_g d), superficial, m/s.
double wen_yu_minimum_fluidization_velocity(const DragInput& in, double gravity);
/// Terminal Reynolds number of one sphere under Schiller-Naumann: C_d(Re) Re^2 = 4 Ar / 3.
double schiller_naumann_terminal_reynolds(double archimedes);

/// Terminal velocity, Wen-Yu minimum fluidization and the Richardson-Zaki exponent n.
struct RichardsonZaki {
  double exponent = 0;              ///< n = ln(Re_mf / Re_t) / ln(eps_mf), dimensionless.
  double terminal_velocity = 0;     ///< U_t of one sphere (Schiller-Naumann), m/s.
  double minimum_fluidization = 0;  ///< U_mf from the Wen-Yu correlation, superficial, m/s.
};
/// n, U_t and U_mf for a particle (in: diameter, densities, viscosity) and eps_mf.
RichardsonZaki richardson_zaki(const DragInput& in, double fluidization_porosity, double gravity);

/// The parts of a closure's K that depend on the porosity and the particle alone (the arctan
/// and the powers of eps): a gas run takes each particle's drag twice a fluid step at the same
/// porosity (for the gas's share, then for the flights) and computes these once. What `first`
/// and `second` hold depends on the closure (drag.cpp); closures without such parts leave them 0.
struct PorosityFactors {
  double porosity = -1.0;  ///< The eps they were taken at (-1: none).
  double first = 0.0, second = 0.0;
};

/// A closure chosen by kind with its parameters: what the coupling calls per particle.
class DragClosure {
 public:
  /// `fluidization_porosity`: eps_mf of the Richardson-Zaki exponent; `gravity`: |g|, m/s^2.
  explicit DragClosure(DragClosureKind kind, double fluidization_porosity = 0.4,
                       double gravity = 9.81);

  /// K of one particle, kg/s: drag force K (u - v), relaxation time m / K.
  double drag_coefficient(const DragInput& in) const;
  /// The factors of K that depend on in.porosity and the particle alone (not on the slip).
  PorosityFactors porosity_factors(const DragInput& in) const;
  /// K as drag_coefficient(in), bit for bit, from factors that porosity_factors took for the
  /// same particle at the same porosity (factors.porosity == in.porosity) and any slip.
  double drag_coefficient(const DragInput& in, const PorosityFactors& factors) const;
  /// Whether K reads DragInput::sauter_diameter (the polydisperse closures).
  bool reads_sauter_diameter() const { return kind_ == DragClosureKind::Beetstra; }
  /// beta = K (1 - eps) / V_p, kg/(m^3 s) (d = in.diameter).
  double momentum_exchange(const DragInput& in) const;
  /// Terminal velocity of one sphere in still gas, eps = 1: K U = V_p (rho_p - rho_g) g, m/s.
  double terminal_velocity(const DragInput& in) const;
  /// Superficial gas velocity that fluidizes a bed at porosity eps_mf, m/s. Per unit volume of a
  /// bed at rest with interstitial u = U / eps: gas 0 = -eps dp/dz - eps rho_g g - beta u;
  /// particles 0 = -(1 - eps) rho_p g - (1 - eps) dp/dz + beta u. Eliminating dp/dz:
  /// beta u / eps = (1 - eps)(rho_p - rho_g) g (the frictional pressure gradient carries the
  /// buoyant weight), i.e. per particle K u = eps V_p (rho_p - rho_g) g.
  double minimum_fluidization_velocity(const DragInput& in, double bed_porosity) const;

 private:
  /// The Richardson-Zaki exponent n of schiller_naumann for the particle of `in`.
  double richardson_zaki_exponent(const DragInput& in) const;

  DragClosureKind kind_;
  double fluidization_porosity_;
  double gravity_;
};

}  // namespace carom
