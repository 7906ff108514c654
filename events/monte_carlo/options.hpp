#pragma once
/// The settings of the Monte Carlo collision method that a scene gives ([monte_carlo], and the
/// flight model of [flight]); SCENES.md documents the keys.
#include <cstdint>

#include "core/flight_model.hpp"

namespace carom {

/// How the collision frequency of a particle with the partners of one species is computed
/// (R1, V1: the particle; R0, <V0>, n: the partners' mean radius, mean velocity and number
/// density in the particle's collision cell).
enum class CollisionFrequency {
  /// Oesterle & Petitjean: nu = sqrt(2) pi (R1 + R0)^2 |V1 - <V0>| n; the partner's velocity
  /// of a collision is drawn from the local Gaussians.
  MeanVelocity,
  /// Kinetic theory: nu = pi (R1 + R0)^2 <|V1 - V0|> n, the mean over the local Gaussian
  /// partner distribution, estimated by sampling (Sommerfeld): each trial draws a partner and
  /// collides with the rate of its own relative speed, so the partners of collisions are
  /// weighted by |V1 - V0| as in a real gas.
  MeanRelativeSpeed,
};

/// Where a collision's fictitious partner comes from.
enum class PartnerModel {
  /// Oesterle & Petitjean, Sommerfeld: velocity drawn from the Gaussians of the cell's mean and
  /// standard deviation of each component (the particle itself left out). Fitted to the k
  /// particles of one cell at one step, it heats an elastic gas by about 0.1/k of its energy
  /// per collision (engine.hpp).
  Gaussian,
  /// The velocity and spin of one of the other particles of the cell (of the partner's
  /// species), picked at random, as they were at the step start: the partners are the cell's
  /// own velocity distribution, so an elastic gas keeps its mean energy (to first order in the
  /// step) however few particles a cell holds. The partner's radius and mass stay the species'
  /// mean in the cell, as for Gaussian.
  CellParticle,
  /// The cell's mean velocity and mean spin of the partner's species, without fluctuations
  /// (the model "without partner velocity fluctuations" of the duct studies): the collision
  /// frequency is then pi (R1 + R0)^2 n |V1 - <V0>|, a Maxwellian gas's mean rate over
  /// sqrt(2) (mean speed against mean relative speed).
  CellMean,
};

/// The contact value that multiplies nu (excluded volume).
enum class ContactValue {
  None,    ///< 1: the dilute (Boltzmann) limit.
  Enskog,  ///< The Boublik-Mansoori-Carnahan-Starling-Leland g_ij of the cell's solid fraction.
};

struct MonteCarloOptions {
  /// Particle time step dt_p, s. <= 0 (default): 0.1 of the shortest mean free time estimated
  /// at the start (and at most the time to cross a quarter collision cell at the rms speed).
  double time_step = 0.0;
  /// Edge of the collision cells, m (cells per axis: the box edge over this, rounded down, at
  /// least 1). <= 0 (default): 4 largest diameters, or more so that a cell holds 32 particles
  /// on average (fewer: Gaussian partners heat an elastic gas more, engine.hpp).
  double cell_size = 0.0;
  CollisionFrequency frequency = CollisionFrequency::MeanRelativeSpeed;
  ContactValue contact_value = ContactValue::None;
  PartnerModel partner = PartnerModel::Gaussian;
  std::uint64_t seed = 1;  ///< Seed of the collision random numbers.
  /// A step whose mean number of collisions per moving particle exceeds this stops the run
  /// (MethodFailure "monte_carlo_step_too_long"): the partner statistics are frozen over a step.
  double max_collisions_per_step = 1.0;
  /// Wall impacts with a normal speed below this are elastic, m/s (the collapse remedy of
  /// core/DESIGN.md, "Collision laws and collapse": a particle resting on a floor under gravity
  /// would otherwise bounce infinitely often in a step). < 0 (default): |g| dt_p / 20, so a bounce
  /// it leaves lasts at least dt_p / 10 (0 without gravity).
  double elastic_below_speed = -1.0;
  /// Ballistic (gravity only) or Relax (each particle's RelaxFlight of the fluid step, flown
  /// exactly). Kick scenes fly ballistic here; the kicks are the gas coupling's.
  FlightModel flight_model = FlightModel::Ballistic;
};

}  // namespace carom
