#pragma once
/// Drawing a fictitious collision partner and the geometry of its impact (the Monte Carlo
/// method's random parts, apart from when a collision happens).
#include "core/rng.hpp"
#include "core/vec3.hpp"
#include "events/monte_carlo/collision_grid.hpp"
#include "events/monte_carlo/options.hpp"

namespace carom {

/// A partner velocity from the local statistics: each component an independent Gaussian with
/// the cell's mean and standard deviation (anisotropic), m/s.
Vec3 sample_partner_velocity(const PartnerStatistics& partners, Rng& rng);

/// The unit contact normal (from the partner's centre to the particle's) of an impact with
/// relative velocity g = V1 - V0 (|g| > 0): the impact point uniform over the collision
/// cross-section, the disc of radius R1 + R0 perpendicular to g. With b / (R1 + R0) = sqrt(u1)
/// (uniform over the disc's area) and an azimuth 2 pi u2 about g:
///   n = -sqrt(1 - b^2/(R1+R0)^2) g/|g| + (b/(R1+R0)) e(azimuth),  so g . n < 0 (approaching).
Vec3 sample_impact_normal(const Vec3& relative_velocity, Rng& rng);

/// The factor that multiplies the collision frequency of a particle of diameter d1 (m) with
/// partners of diameter d0 (m): 1, or (Enskog) the mixture contact value
/// bmcsl_contact_value (core/contact_value.hpp). phi: the cell's solid fraction (capped at 0.6,
/// where the formula has long left the fluid branch), xi2 in 1/m.
double contact_value(ContactValue kind, double solid_fraction, double xi2, double d1, double d0);

}  // namespace carom
