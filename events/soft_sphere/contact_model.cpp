#include "events/soft_sphere/contact_model.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "events/soft_sphere/hertz_damping.hpp"

namespace carom {

namespace {

constexpr double kPi = std::numbers::pi;

void check_material(const ElasticMaterial& m) {
  if (!(m.young_modulus > 0.0 && std::isfinite(m.young_modulus)))
    throw std::invalid_argument("Young's modulus " + std::to_string(m.young_modulus) +
                                " Pa must be > 0");
  if (!(m.poisson_ratio >= 0.0 && m.poisson_ratio < 0.5))
    throw std::invalid_argument("Poisson ratio " + std::to_string(m.poisson_ratio) +
                                " is outside [0, 0.5)");
}

/// A body whose mass is <= 0 or infinite is fixed (infinite mass).
bool is_fixed(double mass) { return !(mass > 0.0) || !std::isfinite(mass); }

PairContact build(double reduced_radius, double reduced_mass, double inv_e_star,
                  double inv_g_star, double restitution, double friction,
                  const SoftSphereOptions& options) {
  if (!(restitution > 0.0 && restitution <= 1.0))
    throw std::invalid_argument("restitution e = " + std::to_string(restitution) +
                                " is outside (0, 1]: soft spheres need e > 0 (e = 0 is an "
                                "infinite dashpot)");
  PairContact c;
  c.model = options.model;
  c.reduced_radius = reduced_radius;
  c.reduced_mass = reduced_mass;
  c.friction = friction;
  c.rolling_friction = options.rolling_friction;
  c.restitution = restitution;
  if (options.model == ContactModel::HertzMindlin) {
    const double e_star = 1.0 / inv_e_star, g_star = 1.0 / inv_g_star;
    const double beta = options.damping == HertzDamping::Exact
                            ? hertz_damping_for_restitution(restitution)
                            : liggghts_damping(restitution);
    const double root_r = std::sqrt(reduced_radius);
    c.normal_stiffness = 4.0 / 3.0 * e_star * root_r;
    c.tangential_stiffness = 8.0 * g_star * root_r;
    const double factor = 2.0 * std::sqrt(5.0 / 6.0) * beta;
    c.normal_damping = factor * std::sqrt(2.0 * e_star * root_r * reduced_mass);
    c.tangential_damping = factor * std::sqrt(8.0 * g_star * root_r * reduced_mass);
  } else {
    double k = options.stiffness;
    const double l = std::log(restitution);
    if (k <= 0.0) {
      if (!(options.contact_time > 0.0))
        throw std::invalid_argument("the linear model needs soft_sphere.stiffness (N/m) or "
                                    "soft_sphere.contact_time (s)");
      k = reduced_mass * (kPi * kPi + l * l) / (options.contact_time * options.contact_time);
    }
    const double omega = std::sqrt(k / reduced_mass) / std::sqrt(1.0 + (l / kPi) * (l / kPi));
    c.normal_stiffness = k;
    c.normal_damping = 2.0 * reduced_mass * omega * (-l) / kPi;
    c.tangential_stiffness = options.tangential_stiffness_ratio * k;
    // The tangential oscillator is the normal one scaled: gamma_t / k_t = gamma / k. With the
    // ratio 2/7 a sphere sticking on a wall then oscillates tangentially exactly as it does
    // normally, and rebounds with tangential restitution beta = e (Walton's beta0 = e).
    c.tangential_damping = c.normal_damping * options.tangential_stiffness_ratio;
  }
  return c;
}

}  // namespace

double PairContact::peak_overlap(double v) const {
  if (model == ContactModel::Linear) return v * std::sqrt(reduced_mass / normal_stiffness);
  // (1/2) m* v^2 = (2/5) k_h delta^5/2.
  return std::pow(1.25 * reduced_mass * v * v / normal_stiffness, 0.4);
}

double PairContact::contact_time(double v) const {
  if (model == ContactModel::Linear) {
    const double ratio = normal_damping / (2.0 * reduced_mass);
    return kPi / std::sqrt(normal_stiffness / reduced_mass - ratio * ratio);
  }
  return 2.9432752 * peak_overlap(v) / v;
}

PairContact make_pair_contact(double radius1, double mass1, const ElasticMaterial& a,
                              double radius2, double mass2, const ElasticMaterial& b,
                              double restitution, double friction, const SoftSphereOptions& options) {
  check_material(a);
  check_material(b);
  const bool fixed1 = is_fixed(mass1), fixed2 = is_fixed(mass2);
  if (fixed1 && fixed2) throw std::invalid_argument("a contact between two fixed bodies");
  const double reduced_mass = fixed1 ? mass2 : fixed2 ? mass1 : mass1 * mass2 / (mass1 + mass2);
  const double reduced_radius = radius1 * radius2 / (radius1 + radius2);
  auto inv_e = [](const ElasticMaterial& m) {
    return (1.0 - m.poisson_ratio * m.poisson_ratio) / m.young_modulus;
  };
  auto inv_g = [](const ElasticMaterial& m) {
    return 2.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio) / m.young_modulus;
  };
  return build(reduced_radius, reduced_mass, inv_e(a) + inv_e(b), inv_g(a) + inv_g(b), restitution,
               friction, options);
}

PairContact make_wall_contact(double radius, double mass, const ElasticMaterial& a,
                              const ElasticMaterial& b, double restitution, double friction,
                              const SoftSphereOptions& options) {
  check_material(a);
  check_material(b);
  auto inv_e = [](const ElasticMaterial& m) {
    return (1.0 - m.poisson_ratio * m.poisson_ratio) / m.young_modulus;
  };
  auto inv_g = [](const ElasticMaterial& m) {
    return 2.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio) / m.young_modulus;
  };
  return build(radius, mass, inv_e(a) + inv_e(b), inv_g(a) + inv_g(b), restitution, friction,
               options);
}

}  // namespace carom
