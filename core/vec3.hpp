#pragma once
/// Small vector types shared by every layer of carom.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>

namespace carom {

/// A 3-vector of doubles (SI units of whatever it holds).
using Vec3 = Eigen::Vector3d;

/// "Never": the time of an event that will not happen.
inline constexpr double kNever = std::numeric_limits<double>::infinity();

}  // namespace carom
