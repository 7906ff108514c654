#pragma once
/// The soft-sphere contact of one species pair or species-wall pair: its constants, and the
/// force, stored energy and contact time they give. One formula per model, in one place.
///
/// Normal overlap delta > 0, approach rate delta' (> 0 closing), R* = R1 R2 / (R1 + R2),
/// m* = m1 m2 / (m1 + m2) (a wall or a fixed particle: R*, m* of the moving sphere).
///   Hertz–Mindlin: F_n = k_h delta^3/2 + c_n delta^1/4 delta',   k_h = 4/3 E* sqrt(R*),
///                  k_t = 8 G* sqrt(R* delta),  gamma_t = c_t delta^1/4,
///                  c_n = 2 sqrt(5/6) beta sqrt(2 E* sqrt(R*) m*), c_t likewise with 8 G*
///                  (LIGGGHTS' form; beta from the restitution, hertz_damping.hpp).
///   Linear:        F_n = k delta + gamma delta',  k_t = ratio k,  gamma_t = ratio gamma (the
///                  tangential oscillator is the normal one scaled).
/// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,  1/G* = 2 (2 - nu1)(1 + nu1)/E1 + 2 (2 - nu2)(1 + nu2)/E2.
/// The contact lasts while delta > 0 (the displacement-based end: the dashpot may pull at the
/// end, as in LIGGGHTS without force limiting); Coulomb: |F_t| <= mu max(F_n, 0).
#include <cmath>

#include "events/soft_sphere/options.hpp"

namespace carom {

struct PairContact {
  ContactModel model = ContactModel::HertzMindlin;
  double reduced_radius = 0;    ///< R*, m.
  double reduced_mass = 0;      ///< m*, kg.
  double normal_stiffness = 0;  ///< Hertz: k_h, N/m^1.5; linear: k, N/m.
  double normal_damping = 0;    ///< Hertz: c_n, kg/(s m^1/4); linear: gamma, kg/s.
  double tangential_stiffness = 0;  ///< Hertz: 8 G* sqrt(R*), N/m^1.5; linear: k_t, N/m.
  double tangential_damping = 0;    ///< Hertz: c_t, kg/(s m^1/4); linear: gamma_t, kg/s.
  double friction = 0;          ///< Coulomb mu.
  double rolling_friction = 0;  ///< mu_r of the constant directional torque.
  double restitution = 1;       ///< e the damping was chosen for.

  /// Normal force magnitude (> 0 repulsive) at overlap delta > 0 and approach rate rate, N.
  double normal_force(double delta, double rate) const {
    if (model == ContactModel::Linear) return normal_stiffness * delta + normal_damping * rate;
    const double root = std::sqrt(delta), quarter = std::sqrt(root);
    return normal_stiffness * delta * root + normal_damping * quarter * rate;
  }
  /// The elastic part of the normal force alone, N.
  double normal_elastic_force(double delta) const {
    return model == ContactModel::Linear ? normal_stiffness * delta
                                         : normal_stiffness * delta * std::sqrt(delta);
  }
  /// Normal damping coefficient at overlap delta, kg/s.
  double normal_damping_at(double delta) const {
    return model == ContactModel::Linear ? normal_damping
                                         : normal_damping * std::sqrt(std::sqrt(delta));
  }
  /// Tangential stiffness at overlap delta, N/m.
  double tangential_stiffness_at(double delta) const {
    return model == ContactModel::Linear ? tangential_stiffness
                                         : tangential_stiffness * std::sqrt(delta);
  }
  /// Tangential damping coefficient at overlap delta, kg/s.
  double tangential_damping_at(double delta) const {
    return model == ContactModel::Linear ? tangential_damping
                                         : tangential_damping * std::sqrt(std::sqrt(delta));
  }
  /// Energy stored in the normal spring at overlap delta, J.
  double normal_energy(double delta) const {
    return model == ContactModel::Linear ? 0.5 * normal_stiffness * delta * delta
                                         : 0.4 * normal_stiffness * delta * delta * std::sqrt(delta);
  }
  /// Duration of a binary impact at approach speed v (m/s) with this pair's
  /// damping, s. Hertz: 2.9432752 delta_max / v (the undamped value: damping lengthens it by
  /// a few per cent); linear: pi / omega.
  double contact_time(double v) const;
  /// Stiffness dF/d delta at overlap delta, N/m (the spring of the step-size limit).
  double stiffness_at(double delta) const {
    return model == ContactModel::Linear ? normal_stiffness
                                         : 1.5 * normal_stiffness * std::sqrt(delta);
  }
  /// Peak overlap of an undamped binary impact at approach speed v, m.
  double peak_overlap(double v) const;
};

/// The contact of two spheres (radius, mass; mass <= 0 or infinite: fixed) of materials a, b with
/// restitution e, friction mu and the scene's options. Throws std::invalid_argument (message
/// without a location) when a constant is out of range.
PairContact make_pair_contact(double radius1, double mass1, const ElasticMaterial& a,
                              double radius2, double mass2, const ElasticMaterial& b,
                              double restitution, double friction, const SoftSphereOptions& options);

/// The contact of a sphere (radius, mass, material a) with a flat wall of material b.
PairContact make_wall_contact(double radius, double mass, const ElasticMaterial& a,
                              const ElasticMaterial& b, double restitution, double friction,
                              const SoftSphereOptions& options);

}  // namespace carom
