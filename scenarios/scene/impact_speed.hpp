#pragma once
/// The impact speed: a collision is an impact when its normal approach speed exceeds it
/// (System::is_impact), and every method counts impacts beside its raw collisions.
///
/// Why. A hard-sphere method resolves a lasting contact (a bead resting on others in a dense
/// bed, a cluster pressed together by gravity or the gas) as a chatter of collisions, each at an
/// approach speed of about the speed gravity or the gas adds between two of them: g t, with t
/// of the order of the TC time. Their number grows as the TC time shrinks, and a soft-sphere
/// method counts the whole contact once. An impact is a collision that begins a contact with a
/// speed that owes nothing to that chatter (scenarios/guides/granular_gases.md, "Impacts").
///
/// The default under gravity is kImpactSpeedFraction sqrt(|g| d), d the smallest diameter: the
/// speed of a free fall through 1/200 of that diameter. Without gravity it is 0, and every
/// collision is an impact: a granular gas has no lasting contacts, and its raw count is already
/// the one kinetic theory predicts. A scene sets its own as [analysis] impact_speed (m/s).
#include "core/system.hpp"

namespace carom {

/// The default impact speed as a fraction of sqrt(|g| d_min).
inline constexpr double kImpactSpeedFraction = 0.1;

/// The default impact speed of `system` (its gravity and species), m/s.
double default_impact_speed(const System& system);

}  // namespace carom
