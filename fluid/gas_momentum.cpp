// The momentum equation of the gas solver on one axis's faces (fluid/gas_solver.hpp).
//
// Face f of axis a lies between cells L and R; its control volume is the open area A_f times the
// spacing h_a (half of it, one half cell, on an outlet face). Backward Euler, conservative
// first-order upwind convection, central diffusion:
//   a_P u_f = sum_nb a_nb u_nb + b,
//   a_P = rho eps_f V / dt + beta_f V + sum over the control-volume faces (D + max(F_out, 0)),
//   a_nb = D + max(-F_out, 0),
//   b = rho eps_f^old u_f^old V / dt + beta_f v_s,f V + eps_f rho g_a V - eps_f A_f (p_R - p_L),
// with F_out the mass flow out through a control-volume face (rho times the mean of the volume
// flows eps u A of the two faces it halves) and D = mu eps A / distance. Under-relaxation:
// a_P -> a_P / alpha, b += (1 - alpha) a_P / alpha u_f (last iterate).
//
// Everything but convection, pressure and relaxation is fixed within a step: prepare_momentum
// computes it once, assemble_momentum adds the rest at each SIMPLE iteration.
#include <algorithm>

#include "gas_solver.hpp"
#include "gas_workspace.hpp"

namespace carom {

using gas_detail::direction;
using gas_detail::GasLayout;

void GasSolver::prepare_momentum(int a, const StepInputs& in) {
  const GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  const double rho = gas_.density, mu = gas_.viscosity;
  const Vec3& h = layout.spacing;
  const double full_area = grid_.face_area(a);
  const auto& face_eps = work.face_porosity;

  for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u) {
    const int f = layout.unknown_face[a][u];
    const int left = layout.left[a][f], right = layout.right[a][f];
    const bool full = left >= 0 && right >= 0;
    // Face values: the mean of the cells present (one on an outlet face).
    auto mean = [&](auto field) {
      if (full) return 0.5 * (field(left) + field(right));
      return field(left >= 0 ? left : right);
    };
    const double eps = face_eps[a][f];
    const double eps_old = mean([&](int c) { return work.old_porosity[c]; });
    const double beta = mean([&](int c) { return in.beta[c]; });
    const double solid = mean([&](int c) { return in.solid_velocity[c][a]; });
    const double area = layout.area[a][f];
    const double extent = full ? h[a] : 0.5 * h[a];  // Control-volume length along a, m.
    const double volume = area * extent;
    const double open = area / full_area;  // Open fraction of the face.

    double diagonal = rho * eps * volume / in.dt + beta * volume;
    const double source = rho * eps_old * work.old_velocity[a][f] * volume / in.dt +
                          beta * solid * volume + eps * rho * gravity_[a] * volume;
    std::array<double, 6> diffusion{};
    // Along a: shear across the cell centres of R and L (none through an outlet).
    for (int sign : {-1, 1}) {
      const int cell = sign > 0 ? right : left;
      if (cell >= 0)
        diffusion[direction(a, sign)] =
            mu * in.porosity[cell] * layout.open_fraction[cell] * full_area / h[a];
    }
    // Across b: shear towards the neighbouring face; at a wall or an inlet the tangential
    // velocity is held at 0 half a cell away (an inlet blows normal to its side); free-slip walls
    // and outlets exert no shear.
    for (int b = 0; b < 3; ++b) {
      if (b == a) continue;
      const int c = 3 - a - b;
      for (int sign : {-1, 1}) {
        const int dir = direction(b, sign);
        const int g = layout.neighbour[a][f][dir];
        if (g >= 0) {
          const double shared_open = std::min(open, layout.area[a][g] / full_area);
          const double eps_shared = 0.5 * (eps + face_eps[a][g]);
          diffusion[dir] = mu * eps_shared * extent * h[c] * shared_open / h[b];
        } else if (boundaries_[dir].kind == GasBoundaryKind::Wall ||
                   boundaries_[dir].kind == GasBoundaryKind::Inlet) {
          diagonal += mu * eps * extent * h[c] * open / (0.5 * h[b]);
        }
      }
    }
    work.base_diagonal[a][u] = diagonal;
    work.base_source[a][u] = source;
    work.pressure_area[a][u] = eps * area;
    work.diffusion[a][u] = diffusion;
  }
}

void GasSolver::clear_momentum(int a) {
  double* values = work_->momentum[a].valuePtr();
  std::fill(values, values + work_->momentum[a].nonZeros(), 0.0);
}

void GasSolver::assemble_momentum(int a, std::size_t begin, std::size_t end) {
  const GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  const double rho = gas_.density, alpha = options_.velocity_relaxation;
  double* values = work.momentum[a].valuePtr();
  const auto& flux = work.flux;
  const double outlet_low = boundaries_[2 * a].pressure;
  const double outlet_high = boundaries_[2 * a + 1].pressure;

  for (std::size_t u = begin; u < end; ++u) {
    const int f = layout.unknown_face[a][u];
    const int left = layout.left[a][f], right = layout.right[a][f];
    const double p_left = left >= 0 ? pressure_[left] : outlet_low;
    const double p_right = right >= 0 ? pressure_[right] : outlet_high;
    double diagonal = work.base_diagonal[a][u];
    double source = work.base_source[a][u] - work.pressure_area[a][u] * (p_right - p_left);
    double neighbour_sum = 0.0;
    const auto& slot = layout.momentum_slot[a][u];
    const auto& neighbour = layout.neighbour[a][f];
    for (int dir = 0; dir < 6; ++dir) {
      const auto& faces = layout.convection_faces[a][u][dir];
      const std::vector<double>& q = flux[dir / 2];
      const double outflow =
          (dir % 2 ? 0.5 : -0.5) * rho *
          ((faces[0] >= 0 ? q[faces[0]] : 0.0) + (faces[1] >= 0 ? q[faces[1]] : 0.0));
      const int g = neighbour[dir];
      if (g < 0) {
        // Beyond a side (or through an outlet): gas leaving carries its momentum out; gas
        // entering brings none (walls, inlets: no tangential velocity; outlets: backflow).
        diagonal += std::max(outflow, 0.0);
        continue;
      }
      const double diffusion = work.diffusion[a][u][dir];
      diagonal += diffusion + std::max(outflow, 0.0);
      const double coefficient = diffusion + std::max(-outflow, 0.0);
      neighbour_sum += coefficient;
      if (layout.unknown[a][g] >= 0)
        values[slot[1 + dir]] -= coefficient;
      else
        source += coefficient * velocity_[a][g];  // A fixed face (inlet, wall): known.
    }
    const double relaxed = diagonal / alpha;
    source += (1.0 - alpha) * relaxed * velocity_[a][f];
    values[slot[0]] += relaxed;
    work.diagonal[a][u] = relaxed;
    work.neighbour_sum[a][u] = neighbour_sum;
    work.rhs[a][static_cast<Eigen::Index>(u)] = source;
  }
}

void GasSolver::solve_momentum(int a) {
  const GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  if (layout.unknown_face[a].empty()) return;
  // Solve for the increment from the last iterate, so that the relative tolerance of the linear
  // solve applies to the change (which vanishes as SIMPLE converges).
  Eigen::VectorXd& x = work.solution[a];
  for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u)
    x[u] = velocity_[a][layout.unknown_face[a][u]];
  work.rhs[a] -= work.momentum[a] * x;
  work.momentum_solver[a].compute(work.momentum[a]);
  x += work.momentum_solver[a].solve(work.rhs[a]);
  for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u)
    velocity_[a][layout.unknown_face[a][u]] = x[u];
}

}  // namespace carom
