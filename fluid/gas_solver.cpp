#include "gas_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gas_layout.hpp"

namespace carom {

using gas_detail::direction;
using gas_detail::GasLayout;
using gas_detail::SparseMatrix;

namespace {

const char* const kSideNames[6] = {"x_low", "x_high", "y_low", "y_high", "z_low", "z_high"};

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("gas solver: " + message);
}

/// Number of face cells on a side of axis a (the product of the two other cell counts).
int side_face_cells(const std::array<int, 3>& cells, int axis) {
  return cells[0] * cells[1] * cells[2] / cells[axis];
}

}  // namespace

GasSolver::GasSolver(GasGrid grid, GasProperties gas, std::array<GasBoundary, 6> boundaries,
                     Vec3 gravity, GasSolverOptions options)
    : grid_(std::move(grid)),
      gas_(gas),
      boundaries_(std::move(boundaries)),
      gravity_(gravity),
      options_(options) {
  require(std::isfinite(gas_.density) && gas_.density > 0.0,
          "gas density " + std::to_string(gas_.density) + " kg/m^3 must be positive");
  require(std::isfinite(gas_.viscosity) && gas_.viscosity >= 0.0,
          "gas viscosity " + std::to_string(gas_.viscosity) + " Pa s must be >= 0");
  require(gravity_.allFinite(), "gravity is not finite");
  require(options_.max_iterations >= 1, "max_iterations must be at least 1");
  require(options_.tolerance > 0.0, "tolerance must be positive");
  require(options_.velocity_relaxation > 0.0 && options_.velocity_relaxation <= 1.0,
          "velocity_relaxation must lie in (0, 1]");
  require(options_.pressure_relaxation > 0.0 && options_.pressure_relaxation <= 1.0,
          "pressure_relaxation must lie in (0, 1]");
  require(options_.velocity_floor > 0.0, "velocity_floor must be positive");
  require(options_.linear_tolerance > 0.0, "linear_tolerance must be positive");
  bool inlet = false, outlet = false;
  for (int s = 0; s < 6; ++s) {
    const GasBoundary& b = boundaries_[s];
    const bool periodic = b.kind == GasBoundaryKind::Periodic;
    const bool partner_periodic = boundaries_[s ^ 1].kind == GasBoundaryKind::Periodic;
    require(periodic == partner_periodic,
            std::string("side ") + kSideNames[s] + (periodic ? " is" : " is not") +
                " periodic but " + kSideNames[s ^ 1] + (partner_periodic ? " is" : " is not") +
                "; a periodic axis needs both of its sides periodic");
    inlet = inlet || b.kind == GasBoundaryKind::Inlet;
    outlet = outlet || b.kind == GasBoundaryKind::Outlet;
    require(std::isfinite(b.superficial_velocity),
            std::string("inlet velocity on ") + kSideNames[s] + " is not finite");
    require(std::isfinite(b.pressure),
            std::string("outlet pressure on ") + kSideNames[s] + " is not finite");
    if (!b.jet_profile.empty()) {
      require(b.kind == GasBoundaryKind::Inlet,
              std::string("side ") + kSideNames[s] + " has a jet profile but is no inlet");
      set_inlet_profile(s, b.jet_profile);
    }
  }
  require(!inlet || outlet,
          "an inlet needs an outlet on some side: the incompressible gas entering must leave");

  layout_ = std::make_unique<GasLayout>(grid_, boundaries_);
  work_ = std::make_unique<gas_detail::GasWorkspace>();
  GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  for (int a = 0; a < 3; ++a) {
    velocity_[a].assign(layout.face_count[a], 0.0);
    work.momentum[a] = layout.momentum_pattern[a];
    const auto m = layout.unknown_face[a].size();
    work.rhs[a].setZero(m);
    work.solution[a].setZero(m);
    work.diagonal[a].assign(m, 0.0);
    work.d[a].assign(m, 0.0);
    work.neighbour_sum[a].assign(m, 0.0);
    work.flux[a].assign(layout.face_count[a], 0.0);
  }
  work.pressure = layout.pressure_pattern;
  const int cells = grid_.count();
  work.use_direct = options_.pressure_solver == GasPressureSolver::Direct ||
                    (options_.pressure_solver == GasPressureSolver::Automatic &&
                     cells <= options_.direct_cell_limit);
  if (work.use_direct && work.pressure.rows() > 0) work.direct.analyzePattern(work.pressure);
  work.iterative.setTolerance(options_.linear_tolerance);
  work.momentum_solver.setTolerance(options_.linear_tolerance);
  work.residual.assign(cells, 0.0);

  // Initial pressure: hydrostatic from the first outlet (along its axis), else 0.
  pressure_.assign(cells, 0.0);
  for (int s = 0; s < 6; ++s) {
    if (boundaries_[s].kind != GasBoundaryKind::Outlet) continue;
    const int a = s / 2;
    const double plane = s % 2 ? grid_.upper()[a] : grid_.lower()[a];
    for (int c = 0; c < cells; ++c)
      pressure_[c] =
          boundaries_[s].pressure + gas_.density * gravity_[a] * (grid_.centre(c)[a] - plane);
    break;
  }
}

GasSolver::~GasSolver() = default;
GasSolver::GasSolver(GasSolver&&) noexcept = default;
GasSolver& GasSolver::operator=(GasSolver&&) noexcept = default;

std::array<int, 3> GasSolver::face_counts(int axis) const { return layout_->face_dims[axis]; }

void GasSolver::set_inlet_velocity(int side, double superficial_velocity) {
  require(side >= 0 && side < 6, "side index " + std::to_string(side) + " is not in 0..5");
  require(boundaries_[side].kind == GasBoundaryKind::Inlet,
          std::string("side ") + kSideNames[side] + " is no inlet");
  require(std::isfinite(superficial_velocity),
          std::string("inlet velocity on ") + kSideNames[side] + " is not finite");
  boundaries_[side].superficial_velocity = superficial_velocity;
}

void GasSolver::set_inlet_profile(int side, std::vector<double> profile) {
  require(side >= 0 && side < 6, "side index " + std::to_string(side) + " is not in 0..5");
  require(boundaries_[side].kind == GasBoundaryKind::Inlet,
          std::string("side ") + kSideNames[side] + " is no inlet");
  const int expected = side_face_cells(grid_.cells(), side / 2);
  require(profile.empty() || static_cast<int>(profile.size()) == expected,
          std::string("the jet profile of ") + kSideNames[side] + " has " +
              std::to_string(profile.size()) + " values; the side has " +
              std::to_string(expected) + " face cells");
  for (double v : profile)
    require(std::isfinite(v), std::string("jet profile of ") + kSideNames[side] + " not finite");
  boundaries_[side].jet_profile = std::move(profile);
}

void GasSolver::set_uniform_velocity(const Vec3& u) {
  for (int a = 0; a < 3; ++a)
    for (int f : layout_->unknown_face[a]) velocity_[a][f] = u[a];
}

void GasSolver::check_inputs(const StepInputs& in) const {
  const auto cells = static_cast<std::size_t>(grid_.count());
  require(std::isfinite(in.dt) && in.dt > 0.0,
          "time step " + std::to_string(in.dt) + " s must be positive");
  require(in.porosity.size() == cells && in.beta.size() == cells &&
              in.solid_velocity.size() == cells,
          "porosity, beta and solid velocity need one value per cell (" + std::to_string(cells) +
              "); got " + std::to_string(in.porosity.size()) + ", " +
              std::to_string(in.beta.size()) + ", " + std::to_string(in.solid_velocity.size()));
  for (std::size_t c = 0; c < cells; ++c) {
    require(in.porosity[c] > 0.0 && in.porosity[c] <= 1.0,
            "porosity " + std::to_string(in.porosity[c]) + " of cell " + std::to_string(c) +
                " is outside (0, 1] (or NaN); floor it (gas.min_porosity) before the solver");
    require(std::isfinite(in.beta[c]) && in.beta[c] >= 0.0,
            "drag coefficient beta " + std::to_string(in.beta[c]) + " kg/m^3/s of cell " +
                std::to_string(c) + " must be finite and >= 0");
    require(in.solid_velocity[c].allFinite(),
            "solid velocity of cell " + std::to_string(c) + " is not finite");
  }
}

double GasSolver::face_porosity(int axis, int face, std::span<const double> porosity) const {
  const int left = layout_->left[axis][face], right = layout_->right[axis][face];
  if (left >= 0 && right >= 0) return 0.5 * (porosity[left] + porosity[right]);
  return porosity[left >= 0 ? left : right];
}

void GasSolver::set_fixed_faces(const StepInputs& in) {
  const GasLayout& layout = *layout_;
  for (int a = 0; a < 3; ++a) {
    for (int f = 0; f < layout.face_count[a]; ++f) {
      if (layout.unknown[a][f] >= 0) continue;
      velocity_[a][f] = 0.0;
      const int left = layout.left[a][f], right = layout.right[a][f];
      if (layout.area[a][f] == 0.0 || (left >= 0 && right >= 0)) continue;
      const int side = left < 0 ? 2 * a : 2 * a + 1;
      const GasBoundary& b = boundaries_[side];
      if (b.kind != GasBoundaryKind::Inlet) continue;
      // Superficial velocity into the domain, uniform or from the jet profile.
      double superficial = b.superficial_velocity;
      if (!b.jet_profile.empty()) {
        const auto ijk = layout.face_coordinates(a, f);
        const int first = a == 0 ? 1 : 0, second = a == 2 ? 1 : 2;
        superficial = b.jet_profile[ijk[first] + layout.cells[first] * ijk[second]];
      }
      const int cell = left >= 0 ? left : right;
      velocity_[a][f] = (side % 2 ? -superficial : superficial) / in.porosity[cell];
    }
  }
}

void GasSolver::compute_fluxes(const StepInputs& in) {
  const GasLayout& layout = *layout_;
  for (int a = 0; a < 3; ++a)
    for (int f = 0; f < layout.face_count[a]; ++f)
      work_->flux[a][f] = layout.area[a][f] == 0.0
                              ? 0.0
                              : face_porosity(a, f, in.porosity) * velocity_[a][f] *
                                    layout.area[a][f];
}

double GasSolver::continuity_imbalance(const StepInputs& in) {
  // Residual of each cell: d(eps V)/dt + net outflow, m^3/s; scaled by the largest face flow.
  const GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  double scale = 0.0;
  for (int a = 0; a < 3; ++a) {
    scale = std::max(scale, options_.velocity_floor * grid_.face_area(a));
    for (double q : work.flux[a]) scale = std::max(scale, std::abs(q));
  }
  double largest = 0.0;
  for (int c = 0; c < grid_.count(); ++c) {
    if (layout.open_fraction[c] <= gas_detail::kClosedFraction) {
      work.residual[c] = 0.0;
      continue;
    }
    const double storage =
        (in.porosity[c] - work.old_porosity[c]) * layout.open_volume[c] / in.dt;
    double r = storage;
    for (int a = 0; a < 3; ++a)
      r += work.flux[a][layout.plus_face(a, c)] - work.flux[a][layout.minus_face(a, c)];
    work.residual[c] = r;
    scale = std::max(scale, std::abs(storage));
    largest = std::max(largest, std::abs(r));
  }
  return largest / scale;
}

GasStepReport GasSolver::step(double dt, std::span<const double> porosity,
                              std::span<const double> beta,
                              std::span<const Vec3> solid_velocity) {
  const StepInputs in{dt, porosity, beta, solid_velocity};
  check_inputs(in);
  const GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  if (has_old_porosity_)
    work.old_porosity = old_porosity_;
  else
    work.old_porosity.assign(porosity.begin(), porosity.end());
  work.old_velocity = velocity_;
  set_fixed_faces(in);

  GasStepReport report;
  const double alpha_p = options_.pressure_relaxation;
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    report.iterations = iteration;
    // 1. Momentum predictor with the current pressure (convecting fluxes of the last iterate).
    compute_fluxes(in);
    work.iterate = velocity_;
    for (int a = 0; a < 3; ++a) {
      if (layout.unknown_face[a].empty()) continue;
      assemble_momentum(a, in);
      // Guess: the last iterate (a function of the state alone, so restores are exact).
      for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u)
        work.solution[a][u] = velocity_[a][layout.unknown_face[a][u]];
      work.momentum_solver.compute(work.momentum[a]);
      work.solution[a] = work.momentum_solver.solveWithGuess(work.rhs[a], work.solution[a]);
      for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u)
        velocity_[a][layout.unknown_face[a][u]] = work.solution[a][u];
    }
    double speed = options_.velocity_floor, change = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int f = 0; f < layout.face_count[a]; ++f) {
        speed = std::max(speed, std::abs(velocity_[a][f]));
        change = std::max(change, std::abs(velocity_[a][f] - work.iterate[a][f]));
      }
    report.velocity_change = change / speed;
    // 2. Mass imbalance of the predicted velocities: the right side of the correction.
    compute_fluxes(in);
    report.predicted_mass_imbalance = continuity_imbalance(in);
    // 3. Pressure correction (matrix and factorisation once per step: d frozen).
    if (work.pressure.rows() > 0) {
      if (iteration == 1) {
        for (int a = 0; a < 3; ++a)
          for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u) {
            const int f = layout.unknown_face[a][u];
            work.d[a][u] =
                face_porosity(a, f, porosity) * layout.area[a][f] /
                (work.diagonal[a][u] - (options_.consistent ? work.neighbour_sum[a][u] : 0.0));
          }
        assemble_pressure_correction(in);
        if (work.use_direct) {
          work.direct.factorize(work.pressure);
          if (work.direct.info() != Eigen::Success)
            throw std::runtime_error("gas solver: pressure-correction factorisation failed");
        } else {
          work.iterative.compute(work.pressure);
        }
      }
      work.pressure_rhs.resize(static_cast<Eigen::Index>(layout.active_cell.size()));
      for (std::size_t u = 0; u < layout.active_cell.size(); ++u)
        work.pressure_rhs[u] = -work.residual[layout.active_cell[u]];
      if (work.use_direct)
        work.correction = work.direct.solve(work.pressure_rhs);
      else
        work.correction = work.iterative.solve(work.pressure_rhs);
      auto correction_at = [&](int cell) {
        return cell >= 0 && layout.active[cell] >= 0 ? work.correction[layout.active[cell]] : 0.0;
      };
      for (int a = 0; a < 3; ++a)
        for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u) {
          const int f = layout.unknown_face[a][u];
          velocity_[a][f] -= work.d[a][u] * (correction_at(layout.right[a][f]) -
                                             correction_at(layout.left[a][f]));
        }
      for (std::size_t u = 0; u < layout.active_cell.size(); ++u)
        pressure_[layout.active_cell[u]] += alpha_p * work.correction[u];
    }
    if (report.predicted_mass_imbalance < options_.tolerance &&
        report.velocity_change < options_.tolerance) {
      report.converged = true;
      break;
    }
  }

  // Final state: continuity of the corrected velocities and the flows through the sides.
  compute_fluxes(in);
  mass_imbalance_ = continuity_imbalance(in);
  report.mass_imbalance = mass_imbalance_;
  outflow_.fill(0.0);
  for (int a = 0; a < 3; ++a)
    for (int f = 0; f < layout.face_count[a]; ++f) {
      if (layout.left[a][f] < 0) outflow_[2 * a] -= work.flux[a][f];
      if (layout.right[a][f] < 0) outflow_[2 * a + 1] += work.flux[a][f];
    }
  for (int a = 0; a < 3; ++a)
    for (double u : velocity_[a])
      if (!std::isfinite(u))
        throw std::runtime_error(
            "gas solver: the velocities diverged (not finite); reduce the fluid time step or the "
            "under-relaxation factors");
  old_porosity_.assign(porosity.begin(), porosity.end());
  has_old_porosity_ = true;
  return report;
}

void GasSolver::assemble_pressure_correction(const StepInputs& in) {
  // Continuity of cell c with u_f = u*_f - d_f (p'_R - p'_L): sum over its faces of
  // k_f (p'_c - p'_across) = -residual_c, k_f = eps_f A_f d_f (p' = 0 on an outlet).
  const GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  double* values = work.pressure.valuePtr();
  std::fill(values, values + work.pressure.nonZeros(), 0.0);
  for (std::size_t u = 0; u < layout.active_cell.size(); ++u) {
    const int c = layout.active_cell[u];
    for (int a = 0; a < 3; ++a)
      for (int sign : {-1, 1}) {
        int face = -1;
        const int other = layout.across(a, sign, c, face);
        const int unknown = layout.unknown[a][face];
        if (unknown < 0 || other == c) continue;
        const double k =
            face_porosity(a, face, in.porosity) * layout.area[a][face] * work.d[a][unknown];
        values[layout.pressure_slot[u][0]] += k;
        const int slot = layout.pressure_slot[u][1 + direction(a, sign)];
        if (slot >= 0) values[slot] -= k;
      }
  }
}

bool GasSolver::face_pressure_gradient(int axis, int face, double& gradient) const {
  const GasLayout& layout = *layout_;
  if (layout.unknown[axis][face] < 0) return false;
  const int left = layout.left[axis][face], right = layout.right[axis][face];
  const double h = layout.spacing[axis];
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
    u[a] = 0.5 * (velocity_[a][layout_->minus_face(a, cell)] +
                  velocity_[a][layout_->plus_face(a, cell)]);
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

double GasSolver::boundary_outflow(int side) const { return outflow_.at(side); }

std::vector<double> GasSolver::save_state() const {
  std::vector<double> state;
  for (int a = 0; a < 3; ++a) state.insert(state.end(), velocity_[a].begin(), velocity_[a].end());
  state.insert(state.end(), pressure_.begin(), pressure_.end());
  if (has_old_porosity_)
    state.insert(state.end(), old_porosity_.begin(), old_porosity_.end());
  else
    state.insert(state.end(), pressure_.size(), 1.0);
  state.push_back(has_old_porosity_ ? 1.0 : 0.0);
  return state;
}

void GasSolver::restore_state(std::span<const double> state) {
  const std::size_t cells = pressure_.size();
  const std::size_t expected =
      velocity_[0].size() + velocity_[1].size() + velocity_[2].size() + 2 * cells + 1;
  require(state.size() == expected, "a saved gas state of " + std::to_string(state.size()) +
                                        " values does not fit this grid (" +
                                        std::to_string(expected) + " expected)");
  auto next = state.begin();
  for (int a = 0; a < 3; ++a) {
    std::copy(next, next + velocity_[a].size(), velocity_[a].begin());
    next += velocity_[a].size();
  }
  std::copy(next, next + cells, pressure_.begin());
  next += cells;
  has_old_porosity_ = state.back() != 0.0;
  if (has_old_porosity_)
    old_porosity_.assign(next, next + cells);
  else
    old_porosity_.clear();
}

}  // namespace carom
