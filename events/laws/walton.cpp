#include "events/laws/walton.hpp"

#include <cmath>

namespace carom {

namespace {
double kinetic_energy(const ContactBody& b) {
  double energy = 0.0;
  if (b.inverse_mass > 0.0) energy += 0.5 * b.velocity.squaredNorm() / b.inverse_mass;
  if (b.inverse_inertia > 0.0) energy += 0.5 * b.spin.squaredNorm() / b.inverse_inertia;
  return energy;
}
}  // namespace

CollisionOutcome collide(const ContactLaw& law, const Vec3& n, ContactBody body1, ContactBody body2) {
  CollisionOutcome outcome;
  const Vec3 contact_velocity =
      body1.velocity - body2.velocity - (body1.radius * body1.spin + body2.radius * body2.spin).cross(n);
  const double normal_speed = contact_velocity.dot(n);  // g . n, negative when approaching
  if (normal_speed >= 0.0) return outcome;
  const Vec3 tangential = contact_velocity - normal_speed * n;
  const double tangential_speed = tangential.norm();

  const double reduced_mass = 1.0 / (body1.inverse_mass + body2.inverse_mass);
  const double e = law.restitution;
  const double normal_impulse = -reduced_mass * (1.0 + e) * normal_speed;  // > 0, along n
  double beta = law.tangential_restitution;
  const double sticking_need = (2.0 / 7.0) * (1.0 + beta) * tangential_speed;
  const double friction_limit = (1.0 + e) * (-normal_speed);
  if (sticking_need > law.sticking_friction() * friction_limit) {
    beta = -1.0 + 3.5 * law.friction * friction_limit / tangential_speed;
    outcome.sliding = true;
  }
  const double energy_before = kinetic_energy(body1) + kinetic_energy(body2);
  outcome.impulse = normal_impulse * n - (2.0 / 7.0) * reduced_mass * (1.0 + beta) * tangential;

  const Vec3 torque_arm = n.cross(outcome.impulse);
  body1.velocity += body1.inverse_mass * outcome.impulse;
  body2.velocity -= body2.inverse_mass * outcome.impulse;
  body1.spin -= (body1.radius * body1.inverse_inertia) * torque_arm;
  body2.spin -= (body2.radius * body2.inverse_inertia) * torque_arm;
  outcome.dissipated = energy_before - kinetic_energy(body1) - kinetic_energy(body2);
  return outcome;
}

}  // namespace carom
