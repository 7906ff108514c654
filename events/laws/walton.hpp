#pragma once
/// Walton's e / mu / beta0 impulse law for sphere-sphere and sphere-wall collisions.
#include "core/contact_law.hpp"
#include "core/vec3.hpp"

namespace carom {

/// One side of a contact. A wall is a body with zero inverse mass and zero inverse inertia.
struct ContactBody {
  Vec3& velocity;          ///< v, m/s (updated).
  Vec3& spin;              ///< w, rad/s (updated).
  double inverse_mass;     ///< 1/m, 1/kg (0 for a wall).
  double radius;           ///< a, m (lever arm from centre to contact).
  double inverse_inertia;  ///< 1/I, 1/(kg m^2) (0 for a wall).
};

/// What one collision did.
struct CollisionOutcome {
  Vec3 impulse = Vec3::Zero();  ///< J, the impulse on body 1, N s.
  double dissipated = 0;        ///< Kinetic energy lost (translational + rotational), J.
  bool sliding = false;         ///< True when Coulomb friction limited the tangential impulse.
};

/// Applies the law to bodies 1 and 2 touching with unit normal n pointing from 2 to 1.
///   g = v1 - v2 - (a1 w1 + a2 w2) x n,  m12 = 1 / (1/m1 + 1/m2),
///   J = -m12 (1+e) g_n - (2/7) m12 (1+beta) g_t,
///   beta = beta0 when (2/7)(1+beta0)|g_t| <= mu_s (1+e)|g_n| (sticking), else
///   beta = -1 + (7/2) mu (1+e) |g_n| / |g_t| (sliding).
///   v1 += J/m1, v2 -= J/m2, w1 -= (a1/I1) n x J, w2 -= (a2/I2) n x J.
/// The factor 2/7 is the tangential effective mass of solid spheres, I = (2/5) m a^2.
/// A separating or grazing contact (g . n >= 0) gets no impulse.
CollisionOutcome collide(const ContactLaw& law, const Vec3& normal, ContactBody body1,
                         ContactBody body2);

}  // namespace carom
