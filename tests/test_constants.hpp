#pragma once
/// Constants shared by the tests: one home for each, so that test files can be compiled together
/// (the release preset's unity build) without two definitions of one name.
#include <limits>
#include <numbers>

#include "core/vec3.hpp"

namespace carom::test {

/// pi.
inline constexpr double kPi = std::numbers::pi;
/// Machine epsilon of double, the unit of the round-off tolerances.
inline constexpr double kEps = std::numeric_limits<double>::epsilon();
/// Standard gravity of the test scenes, m/s^2 (its magnitude).
inline constexpr double kGravity = 9.81;
/// The same gravity as a vector along -z, m/s^2.
inline const Vec3 kGravityVector(0.0, 0.0, -kGravity);

}  // namespace carom::test
