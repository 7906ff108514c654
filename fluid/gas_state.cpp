// The gas solver's inputs between steps, fields at cells and its state for checkpoints
// (fluid/gas_solver.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "gas_solver.hpp"
#include "gas_workspace.hpp"

namespace carom {

using gas_detail::fail;
using gas_detail::GasLayout;
using gas_detail::kSideNames;
using gas_detail::require;

std::array<int, 3> GasSolver::face_counts(int axis) const {
  return layout_->face_dims[axis];
}

// Both setters run every fluid step (the inlet's ramp and jets): messages only on failure.
void GasSolver::set_inlet_velocity(int side, double superficial_velocity) {
  check_inlet_side(side);
  if (!std::isfinite(superficial_velocity))
    fail(std::string("inlet velocity on ") + kSideNames[side] + " is not finite");
  boundaries_[side].superficial_velocity = superficial_velocity;
}

void GasSolver::set_inlet_profile(int side, std::vector<double> profile) {
  check_inlet_side(side);
  const int expected = gas_detail::side_face_cells(grid_.cells(), side / 2);
  if (!profile.empty() && static_cast<int>(profile.size()) != expected)
    fail(std::string("the jet profile of ") + kSideNames[side] + " has " +
         std::to_string(profile.size()) + " values; the side has " + std::to_string(expected) +
         " face cells");
  for (double v : profile)
    if (!std::isfinite(v)) fail(std::string("jet profile of ") + kSideNames[side] + " not finite");
  boundaries_[side].jet_profile = std::move(profile);
}

void GasSolver::check_inlet_side(int side) const {
  if (side < 0 || side >= 6) fail("side index " + std::to_string(side) + " is not in 0..5");
  if (boundaries_[side].kind != GasBoundaryKind::Inlet)
    fail(std::string("side ") + kSideNames[side] + " is no inlet");
}

void GasSolver::set_uniform_velocity(const Vec3& u) {
  for (int a = 0; a < 3; ++a)
    for (int f : layout_->unknown_face[a]) velocity_[a][f] = u[a];
}

bool GasSolver::face_pressure_gradient(int axis, int face, double& gradient) const {
  const GasLayout& layout = *layout_;
  const int left = layout.left[axis][face], right = layout.right[axis][face];
  const double h = layout.spacing[axis];
  if (layout.unknown[axis][face] < 0) {
    // Fixed faces: an inlet's gradient across its half cell, once a step has set the drop.
    if (!has_old_porosity_ || !is_inlet_face(axis, face)) return false;
    gradient = (left < 0 ? -inlet_drop_[axis][face] : inlet_drop_[axis][face]) / (0.5 * h);
    return true;
  }
  if (left >= 0 && right >= 0)
    gradient = (pressure_[right] - pressure_[left]) / h;
  else if (left >= 0)
    gradient = (boundaries_[2 * axis + 1].pressure - pressure_[left]) / (0.5 * h);
  else
    gradient = (pressure_[right] - boundaries_[2 * axis].pressure) / (0.5 * h);
  return true;
}

Vec3 GasSolver::cell_velocity(int cell) const {
  Vec3 u;
  for (int a = 0; a < 3; ++a)
    u[a] = 0.5 *
           (velocity_[a][layout_->minus_face(a, cell)] + velocity_[a][layout_->plus_face(a, cell)]);
  return u;
}

Vec3 GasSolver::pressure_gradient(int cell) const {
  Vec3 gradient;
  for (int a = 0; a < 3; ++a) {
    double low = 0.0, high = 0.0;
    const bool has_low = face_pressure_gradient(a, layout_->minus_face(a, cell), low);
    const bool has_high = face_pressure_gradient(a, layout_->plus_face(a, cell), high);
    if (has_low && has_high)
      gradient[a] = 0.5 * (low + high);
    else if (has_low || has_high)
      gradient[a] = has_low ? low : high;
    else
      gradient[a] = gas_.density * gravity_[a];
  }
  return gradient;
}

double GasSolver::boundary_outflow(int side) const {
  return outflow_.at(side);
}

double GasSolver::momentum_inflow(int side) const {
  const GasLayout& layout = *layout_;
  const int a = side / 2;
  const bool high = side % 2 == 1;
  double sum = 0.0;
  for (int f = 0; f < layout.face_count[a]; ++f) {
    if (layout.boundary_side(a, f) != side) continue;
    const double eps = has_old_porosity_ ? face_porosity(a, f, old_porosity_) : 1.0;
    const double u = velocity_[a][f];
    sum += eps * layout.area[a][f] * u * u;
  }
  return (high ? -1.0 : 1.0) * gas_.density * sum;
}

GasSolverState GasSolver::state() const {
  GasSolverState state;
  state.face_velocity = velocity_;
  state.pressure = pressure_;
  if (has_old_porosity_) state.previous_porosity = old_porosity_;
  state.inlet_drop = inlet_drop_;
  return state;
}

void GasSolver::set_state(GasSolverState state) {
  auto check = [](const std::vector<double>& values, std::size_t expected,
                  const std::string& what) {
    require(values.size() == expected, "a saved gas state has " + std::to_string(values.size()) +
                                           " " + what + "; this grid has " +
                                           std::to_string(expected));
  };
  static const char* const kAxis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    check(state.face_velocity[a], velocity_[a].size(), std::string(kAxis[a]) + "-face velocities");
    check(state.inlet_drop[a], inlet_drop_[a].size(), std::string(kAxis[a]) + "-face inlet drops");
  }
  check(state.pressure, pressure_.size(), "cell pressures");
  if (!state.previous_porosity.empty())
    check(state.previous_porosity, pressure_.size(), "cell porosities");
  velocity_ = std::move(state.face_velocity);
  pressure_ = std::move(state.pressure);
  has_old_porosity_ = !state.previous_porosity.empty();
  old_porosity_ = std::move(state.previous_porosity);
  inlet_drop_ = std::move(state.inlet_drop);
}

}  // namespace carom
