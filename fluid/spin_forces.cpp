#include "spin_forces.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace carom {

namespace {

/// The index of `name` in `names`; throws std::invalid_argument listing them.
template <std::size_t N>
std::size_t find_name(const std::array<std::string_view, N>& names, std::string_view name,
                      const char* what) {
  for (std::size_t i = 0; i < N; ++i)
    if (name == names[i]) return i;
  std::string message =
      std::string("unknown ") + what + " \"" + std::string(name) + "\"; allowed: ";
  for (std::size_t i = 0; i < N; ++i) message += (i ? ", " : "") + std::string(names[i]);
  throw std::invalid_argument(message);
}
}  // namespace

const std::array<std::string_view, 2>& magnus_lift_names() {
  static const std::array<std::string_view, 2> names{"none", "oesterle_bui_dinh"};
  return names;
}

const std::array<std::string_view, 2>& rotational_torque_names() {
  static const std::array<std::string_view, 2> names{"none", "dennis"};
  return names;
}

MagnusLift parse_magnus_lift(std::string_view name) {
  return static_cast<MagnusLift>(find_name(magnus_lift_names(), name, "Magnus lift model"));
}

RotationalTorque parse_rotational_torque(std::string_view name) {
  return static_cast<RotationalTorque>(
      find_name(rotational_torque_names(), name, "rotational torque model"));
}

double spin_parameter(const SpinForceInput& in) {
  const double slip = in.slip.norm();
  if (slip == 0.0) return std::numeric_limits<double>::infinity();
  return in.diameter * in.relative_rotation.norm() / (2.0 * slip);
}

double oesterle_bui_dinh_lift_coefficient(double spin_parameter, double reynolds) {
  const double gamma = spin_parameter;
  return 0.45 +
         (2.0 * gamma - 0.45) * std::exp(-0.075 * std::pow(gamma, 0.4) * std::pow(reynolds, 0.7));
}

Vec3 oesterle_bui_dinh_lift(const SpinForceInput& in) {
  const double slip = in.slip.norm(), rotation = in.relative_rotation.norm();
  if (slip == 0.0 || rotation == 0.0) return Vec3::Zero();
  const double d = in.diameter;
  const double reynolds = in.gas_density * d * slip / in.gas_viscosity;
  const double cl = oesterle_bui_dinh_lift_coefficient(d * rotation / (2.0 * slip), reynolds);
  return (std::numbers::pi / 8.0 * in.gas_density * d * d * cl * slip / rotation) *
         in.relative_rotation.cross(in.slip);
}

double rotational_reynolds_number(const SpinForceInput& in) {
  return in.gas_density * in.diameter * in.diameter * in.relative_rotation.norm() /
         in.gas_viscosity;
}

double dennis_rotational_coefficient(double rotational_reynolds) {
  const double re = rotational_reynolds;
  if (re <= 32.0) return 64.0 * std::numbers::pi / re;
  return 12.9 / std::sqrt(re) + 128.4 / re;
}

Vec3 dennis_torque(const SpinForceInput& in) {
  const double rotation = in.relative_rotation.norm();
  if (rotation == 0.0) return Vec3::Zero();
  const double a = 0.5 * in.diameter;
  const double a5 = a * a * a * a * a;
  const double cr = dennis_rotational_coefficient(rotational_reynolds_number(in));
  return (0.5 * in.gas_density * a5 * cr * rotation) * in.relative_rotation;
}

Vec3 magnus_lift_force(MagnusLift model, const SpinForceInput& in) {
  switch (model) {
    case MagnusLift::None:
      return Vec3::Zero();
    case MagnusLift::OesterleBuiDinh:
      return oesterle_bui_dinh_lift(in);
  }
  return Vec3::Zero();
}

Vec3 rotational_torque(RotationalTorque model, const SpinForceInput& in) {
  switch (model) {
    case RotationalTorque::None:
      return Vec3::Zero();
    case RotationalTorque::Dennis:
      return dennis_torque(in);
  }
  return Vec3::Zero();
}

}  // namespace carom
