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
#include <algorithm>

#include "gas_layout.hpp"
#include "gas_solver.hpp"

namespace carom {

using gas_detail::direction;
using gas_detail::GasLayout;

void GasSolver::assemble_momentum(int a, const StepInputs& in) {
  const GasLayout& layout = *layout_;
  gas_detail::GasWorkspace& work = *work_;
  const double rho = gas_.density, mu = gas_.viscosity, alpha = options_.velocity_relaxation;
  const Vec3& h = layout.spacing;
  const double full_area = grid_.face_area(a);
  double* values = work.momentum[a].valuePtr();
  std::fill(values, values + work.momentum[a].nonZeros(), 0.0);
  const auto& flux = work.flux;

  for (std::size_t u = 0; u < layout.unknown_face[a].size(); ++u) {
    const int f = layout.unknown_face[a][u];
    const int left = layout.left[a][f], right = layout.right[a][f];
    const bool full = left >= 0 && right >= 0;
    // Face values: the mean of the cells present (one on an outlet face).
    auto mean = [&](auto field) {
      if (full) return 0.5 * (field(left) + field(right));
      return field(left >= 0 ? left : right);
    };
    const double eps = mean([&](int c) { return in.porosity[c]; });
    const double eps_old = mean([&](int c) { return work.old_porosity[c]; });
    const double beta = mean([&](int c) { return in.beta[c]; });
    const double solid = mean([&](int c) { return in.solid_velocity[c][a]; });
    const double area = layout.area[a][f];
    const double extent = full ? h[a] : 0.5 * h[a];  // Control-volume length along a, m.
    const double volume = area * extent;
    const double open = area / full_area;  // Open fraction of the face.

    double diagonal = rho * eps * volume / in.dt + beta * volume;
    double source = rho * eps_old * work.old_velocity[a][f] * volume / in.dt +
                    beta * solid * volume + eps * rho * gravity_[a] * volume;
    const double p_left = left >= 0 ? pressure_[left] : boundaries_[2 * a].pressure;
    const double p_right = right >= 0 ? pressure_[right] : boundaries_[2 * a + 1].pressure;
    source -= eps * area * (p_right - p_left);

    // A neighbouring face g in direction dir: diffusion D and outward mass flow through the
    // shared control-volume face.
    double neighbour_sum = 0.0;
    auto couple = [&](int dir, int g, double diffusion, double outflow) {
      diagonal += diffusion + std::max(outflow, 0.0);
      const double coefficient = diffusion + std::max(-outflow, 0.0);
      neighbour_sum += coefficient;
      const int slot = layout.momentum_slot[a][u][1 + dir];
      if (layout.unknown[a][g] >= 0)
        values[slot] -= coefficient;
      else
        source += coefficient * velocity_[a][g];  // A fixed face (inlet, wall): known.
    };

    // Along a: the control-volume faces at the centres of R and L.
    for (int sign : {-1, 1}) {
      const int cell = sign > 0 ? right : left;
      if (cell < 0) {
        // Outlet face: the boundary itself; zero normal velocity gradient (no diffusion); gas
        // flowing back in brings no momentum.
        diagonal += std::max(sign * rho * flux[a][f], 0.0);
        continue;
      }
      const int g = sign > 0 ? layout.plus_face(a, cell) : layout.minus_face(a, cell);
      const double outflow = sign * rho * 0.5 * (flux[a][f] + flux[a][g]);
      const double diffusion = mu * in.porosity[cell] * layout.open_fraction[cell] * full_area / h[a];
      couple(direction(a, sign), g, diffusion, outflow);
    }

    // Across the other axes b: the control-volume faces halving the b-faces of L and R.
    for (int b = 0; b < 3; ++b) {
      if (b == a) continue;
      const int c = 3 - a - b;
      for (int sign : {-1, 1}) {
        const int dir = direction(b, sign);
        double outflow = 0.0;
        for (int cell : {left, right}) {
          if (cell < 0) continue;
          const int bf = sign > 0 ? layout.plus_face(b, cell) : layout.minus_face(b, cell);
          outflow += sign * rho * 0.5 * flux[b][bf];
        }
        const int g = layout.neighbour[a][f][dir];
        if (g >= 0) {
          const double shared_open = std::min(open, layout.area[a][g] / full_area);
          const double eps_shared = 0.5 * (eps + face_porosity(a, g, in.porosity));
          const double diffusion = mu * eps_shared * extent * h[c] * shared_open / h[b];
          couple(dir, g, diffusion, outflow);
          continue;
        }
        // Beyond side dir: walls and inlets hold the tangential velocity at 0 half a cell away
        // (an inlet blows normal to its side); free-slip walls and outlets exert no shear.
        const GasBoundaryKind kind = boundaries_[dir].kind;
        if (kind == GasBoundaryKind::Wall || kind == GasBoundaryKind::Inlet)
          diagonal += mu * eps * extent * h[c] * open / (0.5 * h[b]);
        diagonal += std::max(outflow, 0.0);
      }
    }

    const double relaxed = diagonal / alpha;
    source += (1.0 - alpha) * relaxed * velocity_[a][f];
    values[layout.momentum_slot[a][u][0]] += relaxed;
    work.diagonal[a][u] = relaxed;
    work.neighbour_sum[a][u] = neighbour_sum;
    work.rhs[a][static_cast<Eigen::Index>(u)] = source;
  }
}

}  // namespace carom
