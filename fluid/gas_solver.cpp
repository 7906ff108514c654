#include "gas_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/side_thread.hpp"
#include "gas_workspace.hpp"

namespace carom {

using gas_detail::direction;
using gas_detail::fail;
using gas_detail::GasLayout;
using gas_detail::kSideNames;
using gas_detail::require;

namespace {

/// Iterations of one iterative linear solve at most (they take 5 to 50).
constexpr int kMaxLinearIterations = 500;

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
    inlet_drop_[a].assign(layout.face_count[a], 0.0);
    work.momentum[a] = layout.momentum_pattern[a];
    const auto m = layout.unknown_face[a].size();
    work.rhs[a].setZero(m);
    work.solution[a].setZero(m);
    work.diagonal[a].assign(m, 0.0);
    work.d[a].assign(m, 0.0);
    work.neighbour_sum[a].assign(m, 0.0);
    work.base_diagonal[a].assign(m, 0.0);
    work.base_source[a].assign(m, 0.0);
    work.pressure_area[a].assign(m, 0.0);
    work.diffusion[a].assign(m, {});
    work.face_porosity[a].assign(layout.face_count[a], 1.0);
    work.flow_area[a].assign(layout.face_count[a], 0.0);
    work.flux[a].assign(layout.face_count[a], 0.0);
  }
  work.pressure = layout.pressure_pattern;
  const int cells = grid_.count();
  const auto& n = grid_.cells();
  const bool flat = n[0] == 1 || n[1] == 1 || n[2] == 1;  // 1-D or 2-D: little fill-in.
  work.use_direct = options_.pressure_solver == GasPressureSolver::Direct ||
                    (options_.pressure_solver == GasPressureSolver::Automatic &&
                     (flat || cells <= options_.direct_cell_limit));
  if (work.pressure.rows() > 0) {
    std::vector<std::array<int, 3>> coordinates;
    for (int c : layout.active_cell) coordinates.push_back(grid_.coordinates(c));
    if (work.use_direct)
      work.direct.analyzePattern(work.pressure);
    else
      work.multigrid.analyze(work.pressure, coordinates);
  }
  for (auto& solver : work.momentum_solver) {
    solver.setTolerance(options_.linear_tolerance);
    solver.setMaxIterations(kMaxLinearIterations);
  }
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

void GasSolver::check_inputs(const StepInputs& in) const {
  // Called every fluid step: each message is built only when its check fails.
  const auto cells = static_cast<std::size_t>(grid_.count());
  if (!(std::isfinite(in.dt) && in.dt > 0.0))
    fail("time step " + std::to_string(in.dt) + " s must be positive");
  if (in.porosity.size() != cells || in.beta.size() != cells || in.solid_velocity.size() != cells)
    fail("porosity, beta and solid velocity need one value per cell (" + std::to_string(cells) +
         "); got " + std::to_string(in.porosity.size()) + ", " + std::to_string(in.beta.size()) +
         ", " + std::to_string(in.solid_velocity.size()));
  for (std::size_t c = 0; c < cells; ++c) {
    if (!(in.porosity[c] > 0.0 && in.porosity[c] <= 1.0))
      fail("porosity " + std::to_string(in.porosity[c]) + " of cell " + std::to_string(c) +
           " is outside (0, 1] (or NaN); floor it (gas.min_porosity) before the solver");
    if (!(std::isfinite(in.beta[c]) && in.beta[c] >= 0.0))
      fail("drag coefficient beta " + std::to_string(in.beta[c]) + " kg/m^3/s of cell " +
           std::to_string(c) + " must be finite and >= 0");
    if (!in.solid_velocity[c].allFinite())
      fail("solid velocity of cell " + std::to_string(c) + " is not finite");
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
      const int side = layout.boundary_side(a, f);
      if (side < 0) continue;
      const GasBoundary& b = boundaries_[side];
      if (b.kind != GasBoundaryKind::Inlet) continue;
      // Superficial velocity into the domain, uniform or from the jet profile.
      double superficial = b.superficial_velocity;
      if (!b.jet_profile.empty()) {
        const auto ijk = layout.face_coordinates(a, f);
        const int first = a == 0 ? 1 : 0, second = a == 2 ? 1 : 2;
        superficial = b.jet_profile[ijk[first] + layout.cells[first] * ijk[second]];
      }
      const int cell = side % 2 ? layout.left[a][f] : layout.right[a][f];
      velocity_[a][f] = (side % 2 ? -superficial : superficial) / in.porosity[cell];
    }
  }
}

void GasSolver::compute_fluxes() {
  gas_detail::GasWorkspace& work = *work_;
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < velocity_[a].size(); ++f)
      work.flux[a][f] = work.flow_area[a][f] * velocity_[a][f];
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
    const double storage = (in.porosity[c] - work.old_porosity[c]) * layout.open_volume[c] / in.dt;
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
                              std::span<const double> beta, std::span<const Vec3> solid_velocity,
                              SideThread* side) {
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
  for (int a = 0; a < 3; ++a)
    for (int f = 0; f < layout.face_count[a]; ++f) {
      work.face_porosity[a][f] = face_porosity(a, f, porosity);
      work.flow_area[a][f] = work.face_porosity[a][f] * layout.area[a][f];
    }
  for (int a = 0; a < 3; ++a) prepare_momentum(a, in);

  GasStepReport report;
  const double alpha_p = options_.pressure_relaxation;
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    report.iterations = iteration;
    // 1. Momentum predictor with the current pressure (convecting fluxes of the last iterate).
    compute_fluxes();
    work.iterate = velocity_;
    auto predict_axis = [&](int a) {
      clear_momentum(a);
      assemble_momentum(a, 0, layout.unknown_face[a].size());
      solve_momentum(a);
    };
    // Each axis reads its own velocities, the fluxes and the pressure, and writes its own
    // matrix, solver and velocities. Three axes on two threads: x here and z on the side thread,
    // each followed by half of y's rows (assembled and solved, an axis takes about the same time
    // as the next), then y solved here; x and y here, z beside, left the side thread idle for
    // a third of the momentum predictor.
    if (side != nullptr) {
      const std::size_t rows = layout.unknown_face[1].size(), half = rows / 2;
      clear_momentum(1);
      side->run_beside(
          [&] {
            predict_axis(2);
            assemble_momentum(1, half, rows);
          },
          [&] {
            predict_axis(0);
            assemble_momentum(1, 0, half);
          });
      solve_momentum(1);
    } else {
      for (int a = 0; a < 3; ++a) predict_axis(a);
    }
    double speed = options_.velocity_floor, change = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int f = 0; f < layout.face_count[a]; ++f) {
        speed = std::max(speed, std::abs(velocity_[a][f]));
        change = std::max(change, std::abs(velocity_[a][f] - work.iterate[a][f]));
      }
    report.velocity_change = change / speed;
    // 2. Mass imbalance of the predicted velocities: the right side of the correction.
    compute_fluxes();
    report.predicted_mass_imbalance = continuity_imbalance(in);
    // 3. Pressure correction (matrix and factorisation once per step: d frozen).
    if (work.pressure.rows() > 0) {
      if (iteration == 1) {
        for (int a = 0; a < 3; ++a)
          for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u) {
            work.d[a][u] =
                work.pressure_area[a][u] /
                (work.diagonal[a][u] - (options_.simplec ? work.neighbour_sum[a][u] : 0.0));
          }
        assemble_pressure_correction();
        if (work.use_direct) {
          work.direct.factorize(work.pressure);
          if (work.direct.info() != Eigen::Success)
            throw std::runtime_error("gas solver: pressure-correction factorisation failed");
        } else {
          work.multigrid.factorize(work.pressure);
        }
      }
      work.pressure_rhs.resize(static_cast<Eigen::Index>(layout.active_cell.size()));
      for (std::size_t u = 0; u < layout.active_cell.size(); ++u)
        work.pressure_rhs[u] = -work.residual[layout.active_cell[u]];
      if (work.use_direct)
        work.correction = work.direct.solve(work.pressure_rhs);
      else
        work.multigrid.solve(work.pressure_rhs, work.correction, options_.linear_tolerance,
                             kMaxLinearIterations);
      auto correction_at = [&](int cell) {
        return cell >= 0 && layout.active[cell] >= 0 ? work.correction[layout.active[cell]] : 0.0;
      };
      for (int a = 0; a < 3; ++a)
        for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u) {
          const int f = layout.unknown_face[a][u];
          velocity_[a][f] -=
              work.d[a][u] * (correction_at(layout.right[a][f]) - correction_at(layout.left[a][f]));
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
  compute_fluxes();
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
  set_inlet_drops(in);
  old_porosity_.assign(porosity.begin(), porosity.end());
  has_old_porosity_ = true;
  return report;
}

bool GasSolver::is_inlet_face(int axis, int face) const {
  const int side = layout_->boundary_side(axis, face);
  return side >= 0 && boundaries_[side].kind == GasBoundaryKind::Inlet;
}

void GasSolver::set_inlet_drops(const StepInputs& in) {
  const GasLayout& layout = *layout_;
  for (int a = 0; a < 3; ++a) {
    const double half = 0.5 * layout.spacing[a];
    for (int f = 0; f < layout.face_count[a]; ++f) {
      if (!is_inlet_face(a, f)) continue;
      const int left = layout.left[a][f], cell = left >= 0 ? left : layout.right[a][f];
      // The half cell's drag is the half of the cell's beta that no face equation holds.
      const double drag = in.beta[cell] * (velocity_[a][f] - in.solid_velocity[cell][a]);
      const double drop = half * (drag / in.porosity[cell] - gas_.density * gravity_[a]);
      inlet_drop_[a][f] = left < 0 ? drop : -drop;
    }
  }
}

void GasSolver::assemble_pressure_correction() {
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
        const double k = work.flow_area[a][face] * work.d[a][unknown];
        values[layout.pressure_slot[u][0]] += k;
        const int slot = layout.pressure_slot[u][1 + direction(a, sign)];
        if (slot >= 0) values[slot] -= k;
      }
  }
}

}  // namespace carom
