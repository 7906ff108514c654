#pragma once
/// Parameters of Walton's three-coefficient impulse law for one pair of surfaces.
#include <stdexcept>
#include <string>

namespace carom {

/// Walton's law: normal restitution e, Coulomb friction mu, tangential restitution beta0.
/// The static/kinetic Coulomb variant is the same law with static_friction != friction
/// and beta0 = 0: a contact sticks when the tangential impulse it needs is at most
/// static_friction * |J_n| and otherwise slides with `friction` (the kinetic coefficient).
struct ContactLaw {
  double restitution = 1.0;              ///< e in [0, 1]: normal restitution.
  double friction = 0.0;                 ///< mu >= 0: (kinetic) Coulomb friction coefficient.
  double tangential_restitution = 0.0;   ///< beta0 in [-1, 1]: -1 smooth, +1 perfectly rough.
  double static_friction = -1.0;         ///< mu_s >= mu, or < 0 for "same as friction".

  /// The static coefficient actually used (mu_s, or mu when none is set).
  double sticking_friction() const { return static_friction < 0 ? friction : static_friction; }

  /// Throws std::invalid_argument naming `where` when a coefficient is out of range.
  void validate(const std::string& where) const {
    auto fail = [&](const std::string& what) {
      throw std::invalid_argument(where + ": " + what);
    };
    if (!(restitution >= 0.0 && restitution <= 1.0))
      fail("restitution e = " + std::to_string(restitution) + " is outside [0, 1]");
    if (!(friction >= 0.0)) fail("friction mu = " + std::to_string(friction) + " must be >= 0");
    if (!(tangential_restitution >= -1.0 && tangential_restitution <= 1.0))
      fail("beta0 = " + std::to_string(tangential_restitution) + " is outside [-1, 1]");
    if (static_friction >= 0.0 && static_friction < friction)
      fail("static friction " + std::to_string(static_friction) +
           " is below the kinetic friction " + std::to_string(friction));
  }
};

}  // namespace carom
