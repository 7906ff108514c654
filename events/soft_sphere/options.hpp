#pragma once
/// The settings of the soft-sphere DEM method (`[soft_sphere]` of a scene, SCENES.md).
#include <cstdint>
#include <optional>
#include <vector>

namespace carom {

/// The normal (and matching tangential) contact force model.
enum class ContactModel {
  HertzMindlin,  ///< Hertz normal force, Mindlin no-slip tangential spring, Tsuji-type damping.
  Linear,        ///< Linear spring-dashpot, normal and tangential.
};

/// How the Hertz damping is chosen from the restitution e.
enum class HertzDamping {
  /// The damping coefficient for which a binary impact rebounds with exactly e (the
  /// dimensionless impact equation solved once per e, hertz_damping.cpp). Default.
  Exact,
  /// LIGGGHTS' (and Tsuji's linearised) formula beta = ln e / sqrt(ln^2 e + pi^2): the rebound
  /// is then close to, not equal to, e. For comparisons with LIGGGHTS.
  Liggghts,
};

/// Elastic constants of one material.
struct ElasticMaterial {
  double young_modulus = 0;  ///< E, Pa (> 0).
  double poisson_ratio = 0;  ///< nu in [0, 0.5).
};

struct SoftSphereOptions {
  ContactModel model = ContactModel::HertzMindlin;
  HertzDamping damping = HertzDamping::Exact;
  /// Elastic constants per species (Hertz–Mindlin), in species order.
  std::vector<ElasticMaterial> species_materials;
  /// Elastic constants per wall; an unset wall is of the same material as the particle that
  /// touches it.
  std::vector<std::optional<ElasticMaterial>> wall_materials;
  /// Linear model: normal stiffness k, N/m (> 0), or 0 to take it from contact_time.
  double stiffness = 0;
  /// Linear model: the binary contact time every pair gets (k = m* (pi^2 + ln^2 e) / t_c^2), s.
  double contact_time = 0;
  /// Linear model: tangential over normal stiffness, k_t / k_n (2/7 makes the tangential and
  /// normal oscillations of a sphere on a wall equally fast).
  double tangential_stiffness_ratio = 2.0 / 7.0;
  /// Rolling resistance coefficient mu_r of the constant directional torque model (0: off).
  double rolling_friction = 0;
  /// Time step, s; 0: step_fraction times the shortest binary contact time of the scene.
  double time_step = 0;
  /// Fraction of the shortest contact time taken as the default step.
  double step_fraction = 0.02;
  /// The largest impact speed expected, m/s, for the Hertz contact time of the default step
  /// (the contact time shortens as v^-1/5); 0: estimated from the initial velocities and the
  /// height a particle can fall.
  double impact_speed = 0;
  /// Verlet-list skin as a fraction of the smallest diameter.
  double skin = 0.3;
  /// The run stops when an overlap exceeds this fraction of the smaller radius of the pair.
  double max_overlap = 0.1;
  /// The run stops when the energy balance (kinetic + potential + elastic + dissipated - gas
  /// work) drifts by more than this fraction of the largest kinetic plus elastic energy seen.
  double max_energy_drift = 0.1;
};

}  // namespace carom
