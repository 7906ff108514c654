#pragma once
/// The least model a scene needs (`carom check`, `carom run --method auto`): the scene's
/// dimensionless numbers, estimated from the scene and its initial state before anything runs,
/// and from them the method, flight model, gas coupling and gas dimensionality to use, each with
/// its reason. The estimates are orders of magnitude (stated with each number); the thresholds
/// are named constants below, each with the reason for its value. Where a shipped chart backs a
/// recommendation, its reason gives the chart's measured numbers and names the chart file
/// (chart_evidence.hpp holds them).
#include <string>
#include <vector>

#include "events/method_factory.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

/// A species' response to the gas.
struct SpeciesNumbers {
  std::string name;
  double mass_share = 0;  ///< Share of the particles' mass.
  double relaxation_time =
      NAN;  ///< tau = U_t / g (Stokes' rho d^2 / (18 mu) without gravity), s; NaN without gas.
  double stokes =
      NAN;  ///< tau / (L / U), L the domain along the inlet's axis; NaN without an inlet.
  double minimum_fluidization =
      NAN;  ///< U_mf of the scene's closure at eps_mf = 0.4, m/s; NaN without gravity or gas.
};

/// The numbers `carom check` reports.
struct SceneNumbers {
  std::vector<SpeciesNumbers> species;
  double solid_fraction = 0;  ///< Solid volume / domain volume.
  /// Solid fraction around a typical particle at t = 0: the solid volume of the other particles
  /// in its sample cell of about 4 largest diameters over the cell's volume, averaged over the
  /// particles (unbiased for a uniform random placement).
  double solid_fraction_seen = 0;
  std::string packing_source;  ///< Where solid_fraction_seen comes from.
  double speed = NAN;  ///< Collision speed scale, m/s (`speed_source` says which).
  std::string speed_source;
  double mean_free_time = NAN;  ///< Enskog at solid_fraction_seen and `speed`, s.
  /// Hertz binary contact time of the largest species at `speed`, s; NaN without elastic
  /// constants (young_modulus).
  double contact_time = NAN;
  std::string contact_source;
  /// The young_modulus (of [[species]], read for soft spheres) the contact time comes from, Pa;
  /// NaN without one. The method advice depends on it and says so.
  double young_modulus = NAN;
  /// Hertz peak overlap of two of the largest species meeting at `speed`, over their radius
  /// (elastic, the deepest a binary impact goes); NaN without elastic constants.
  double peak_overlap = NAN;
  double lasting_share = 0;  ///< Share of the mass expected in lasting contacts.
  std::string lasting_reason;
  double inlet_velocity = 0;  ///< Largest superficial inlet velocity, m/s (0: none).
  double mass_loading = NAN;  ///< Particle mass / gas mass in the domain; NaN without gas.
  double cell_ratio = NAN;    ///< Smallest gas cell edge (axes of > 1 cell) / largest diameter.
  double tube_ratio =
      NAN;            ///< Tube (cylinder wall) or narrowest lateral extent / largest diameter.
  bool tube = false;  ///< tube_ratio is a cylinder's.
  int gas_dimensions_needed =
      0;  ///< 1, 2 or 3: axes wide enough for 2 cells of 3 largest diameters (0: no gas).
  int gas_dimensions =
      0;  ///< The scene's: axes with more than one gas cell, at least 1 (0: no gas).
  double step_ratio = NAN;  ///< Smallest relaxation time / fluid step; NaN without gas.
};

/// One recommendation.
struct Advice {
  std::string topic;     ///< "method", "monte carlo", "soft-sphere step", "soft-sphere
                         ///< stiffness", "flight", "coupling", "gas grid".
  std::string choice;    ///< What to use.
  std::string reason;    ///< Why, with the numbers.
  std::string scene;     ///< What the scene has now.
  bool differs = false;  ///< The scene models more or less than recommended.
};

/// Thresholds (and why).
/// Lasting contacts in at least this share of the mass call for soft spheres: hard spheres then
/// need the TC model, which makes those contacts smooth and elastic (the pinned plug of
/// tests/bench/README.md "Lasting contacts" stops with lasting_contacts).
inline constexpr double kLastingShare = 0.5;
/// A contact lasting this share of the mean free time is not binary (the event-driven method
/// assumes instantaneous binary collisions).
inline constexpr double kContactShare = 0.1;
/// Particle-to-gas mass loading below which the particles' drag changes the gas momentum by
/// less than about 10 %: one-way coupling suffices.
inline constexpr double kOneWayLoading = 0.1;
/// Stokes number above which the gas changes a particle's velocity by less than 1/St per flow
/// time: the gas need not be modelled at all.
inline constexpr double kNoGasStokes = 1e3;
/// Relaxation time / fluid step above which kick flights are accurate (the kick map's
/// first-order error, about 0.35 step / tau, is then below 0.4 %) and stable.
inline constexpr double kKickStepRatio = 100.0;
/// An axis of the gas is resolved only where it holds two cells of this many largest diameters;
/// a narrower axis gets one cell. (Not a bound on the cell size: the shipped beds use cells of 2
/// to 4 diameters, and the fluid map shows what the cell size moves; see the gas grid advice.)
inline constexpr double kCellDiameters = 3.0;

/// Solid fraction taken for a bed whose settling run (initial.settle_time) was not run: between
/// random loose (about 0.55) and random close packing (about 0.64) of spheres. Used only where
/// the placed particles are looser.
inline constexpr double kSettledPacking = 0.6;

/// The numbers of a scene whose initial state has been built (scene.system.particles placed).
/// `settling_skipped`: the scene settles (initial.settle_time) but the particles are as placed;
/// under gravity the solid fraction around a particle is then taken as kSettledPacking.
SceneNumbers scene_numbers(const Scene& scene, bool settling_skipped = false);

/// The recommendation for those numbers: method, flight, coupling, gas grid (the last three
/// only where the scene has a gas or could need one).
std::vector<Advice> recommend(const Scene& scene, const SceneNumbers& numbers);

/// The recommended method (the first advice's choice, as a MethodKind).
MethodKind recommended_method(const std::vector<Advice>& advice);

/// The "least model" section of `carom check`.
std::string describe_recommendation(const SceneNumbers& numbers, const std::vector<Advice>& advice);

}  // namespace carom
