#include "events/monte_carlo/partner_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/contact_value.hpp"

namespace carom {

Vec3 sample_partner_velocity(const PartnerStatistics& partners, Rng& rng) {
  return partners.mean_velocity + partners.velocity_std.cwiseProduct(rng.normal3());
}

Vec3 sample_impact_normal(const Vec3& relative_velocity, Rng& rng) {
  const Vec3 along = relative_velocity.normalized();
  // Any unit vector not parallel to `along`, then two perpendicular axes of the disc.
  const Vec3 helper = std::abs(along.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = along.cross(helper).normalized();
  const Vec3 e2 = along.cross(e1);
  const double offset_squared = rng.uniform();  // (b / (R1 + R0))^2, uniform over the disc's area
  const double azimuth = 2.0 * std::numbers::pi * rng.uniform();
  const double offset = std::sqrt(offset_squared);
  return -std::sqrt(1.0 - offset_squared) * along +
         offset * (std::cos(azimuth) * e1 + std::sin(azimuth) * e2);
}

double contact_value(ContactValue kind, double solid_fraction, double xi2, double d1, double d0) {
  if (kind == ContactValue::None) return 1.0;
  const double phi = std::clamp(solid_fraction, 0.0, 0.6);
  if (solid_fraction > phi) xi2 *= phi / solid_fraction;  // the same cap on the size moment
  return bmcsl_contact_value(phi, xi2, d1, d0);
}

}  // namespace carom
