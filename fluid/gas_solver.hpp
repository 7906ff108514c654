#pragma once
/// The coarse-grid gas solver (core/DESIGN.md, "The gas and the two time scales"): volume-averaged
/// incompressible gas,
///   d(eps)/dt + div(eps u) = 0,
///   rho_g [d(eps u)/dt + div(eps u u)] = -eps grad p + div(eps mu_g grad u) + eps rho_g g
///                                        - beta (u - v_s),
/// u the interstitial gas velocity, p the full pressure (hydrostatic part included), eps the
/// porosity, beta the drag (momentum exchange) coefficient and v_s the solid velocity of a cell.
///
/// Discretisation: finite volumes on a staggered Cartesian grid (GasGrid): p, eps, beta, v_s at
/// cell centres, u normal to each face. Backward Euler in time, first-order upwind convection
/// (conservative form), central diffusion, drag implicit (beta on the diagonal, beta v_s in the
/// source; beta and v_s at a face are the mean of its two cells, as is eps). The nonlinear
/// pressure-velocity system of one step is solved by SIMPLE with under-relaxation, iterated until
/// both the mass imbalance of the momentum-predicted velocities and the change of the velocities
/// fall below GasSolverOptions::tolerance. Each iteration ends with the pressure correction, so
/// the stored velocities satisfy continuity to round-off (Cholesky) or to linear_tolerance times
/// the last predicted imbalance (multigrid): see mass_imbalance().
///
/// Open volumes (cells cut by walls): a cell holds eps * open volume of gas; a face's open area is
/// its full area times the smaller open fraction of its two cells (the cell's own on the boundary);
/// a face's momentum control volume is its open area times the spacing (half the spacing on an
/// outlet face). Cells with no open volume are solid: their faces are closed (u = 0). A 1-D tube of
/// cross-section A is thus nx = ny = 1 with open fraction A / (dx dy) and FreeSlip side walls;
/// a pseudo-2-D bed is nx x 1 x nz. Neither needs a special case: an axis of one non-periodic cell
/// has only (fixed) boundary faces.
///
/// Boundaries (one per side, x-, x+, y-, y+, z-, z+):
///  - Wall: u = 0 on the side; the tangential velocity is 0 at the wall (half a cell from the
///    nearest faces: shear mu eps u / (dx / 2)).
///  - FreeSlip: u = 0 on the side, no shear.
///  - Inlet: the superficial velocity U into the domain is given on each face (uniform, or a
///    per-face profile for jets); u = U / eps_cell there; the gas enters with no tangential
///    velocity (shear as at a wall).
///  - Outlet: the pressure is given on the side; the face velocity is solved from the momentum
///    balance of the half cell next to it; zero normal gradient of the velocity (no viscous
///    stress); gas leaving carries its momentum out, gas flowing back in brings none.
///  - Periodic: both sides of an axis; the faces wrap.
/// Without an outlet the pressure level is fixed by holding one cell's pressure (per connected
/// region of gas) at its initial value.
///
/// Linear solvers (Eigen): each velocity component by BiCGSTAB with a diagonal preconditioner
/// (diagonally dominant matrices), solved for the increment over the last iterate; the pressure
/// correction (symmetric positive definite) by a sparse Cholesky factorisation (SimplicialLDLT,
/// AMD ordering) on 1-D, 2-D and small 3-D grids, else by conjugate gradients preconditioned with
/// an aggregation multigrid V-cycle (fluid/gas_multigrid.hpp: Cholesky fill-in grows too fast in
/// 3-D). The SIMPLE coefficients d are frozen within a step (any d converges to the same
/// solution), so the pressure-correction matrix is factorised once per step. Matrix patterns, the
/// Cholesky analysis and the multigrid levels are built once; values are filled in place.
///
/// Cost of one step (CPU time, Release, g++ 12, one core; a bubbling-bed-like state: eps
/// 0.45..0.75 and Ergun beta in the lower half, free board above, U = 0.3 m/s, dt = 2e-4 s,
/// tolerance 1e-6, linear_tolerance 1e-3; mean over steps 5..30; the first steps from rest take
/// about twice the iterations):
///   grid           cells   SIMPLE 0.7/0.3 (default)   SIMPLEC 0.8/1.0
///   20 x 1 x 60     1200   3.8 ms, 22 iterations      1.7 ms, 7 iterations   (Cholesky)
///   16 x 16 x 40   10240    76 ms, 22 iterations       30 ms, 7 iterations   (multigrid CG)
/// With Cholesky on 16 x 16 x 40 the factorisation alone takes about 0.1 s per step.
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "gas_grid.hpp"

namespace carom {

class SideThread;  // core/side_thread.hpp

namespace gas_detail {
struct GasLayout;
struct GasWorkspace;
}  // namespace gas_detail

/// Constant gas properties.
struct GasProperties {
  double density = 1.2;       ///< rho_g, kg/m^3.
  double viscosity = 1.8e-5;  ///< mu_g, Pa s.
};

/// What holds the gas on one side of the box.
enum class GasBoundaryKind {
  Wall,      ///< No-slip wall: no flow through, no slip along.
  FreeSlip,  ///< Free-slip wall: no flow through, no shear along.
  Inlet,     ///< Given superficial velocity into the domain.
  Outlet,    ///< Given pressure; the gas leaves (or enters) freely.
  Periodic,  ///< Wraps to the opposite side (both sides of the axis must say so).
};

/// The boundary condition on one side of the box.
struct GasBoundary {
  GasBoundaryKind kind = GasBoundaryKind::FreeSlip;  ///< What the side is.
  /// Inlet: superficial velocity eps u into the domain (positive = inflow on either side), m/s.
  double superficial_velocity = 0.0;
  /// Inlet (jets): superficial velocity into the domain of each face cell of the side, m/s; empty:
  /// uniform superficial_velocity. Face cell (i_b, i_c) of the two other axes b < c has index
  /// i_b + n_b i_c (e.g. i + nx j on a z side).
  std::vector<double> jet_profile;
  /// Outlet: pressure on the side, Pa (the full pressure, as the solver's).
  double pressure = 0.0;
};

/// Pressure-correction linear solver.
enum class GasPressureSolver {
  Automatic,  ///< Direct on 1-D and 2-D grids and up to direct_cell_limit cells, else Multigrid.
  Direct,     ///< Sparse Cholesky (SimplicialLDLT), factorised once per step.
  Multigrid,  ///< Conjugate gradients preconditioned by an aggregation-multigrid V-cycle.
};

/// Iteration controls of the SIMPLE loop of one step.
struct GasSolverOptions {
  int max_iterations = 100;  ///< SIMPLE iterations per step at most.
  /// Convergence: mass imbalance (relative to the largest face volume flow) and velocity change
  /// (relative to the largest face velocity) both below this, dimensionless.
  double tolerance = 1e-6;
  double velocity_relaxation = 0.7;  ///< Momentum under-relaxation alpha_u, in (0, 1].
  double pressure_relaxation = 0.3;  ///< Pressure-correction under-relaxation alpha_p, in (0, 1].
  /// SIMPLEC (Van Doormaal & Raithby 1984) instead of SIMPLE: d = eps A / (a_P - sum a_nb),
  /// stable with pressure_relaxation = 1; with velocity_relaxation 0.8 it needs about a third of
  /// the iterations of SIMPLE 0.7/0.3 in fluidised beds (see the table above).
  bool simplec = false;
  /// Velocities below this are insignificant in the convergence test (a floor of the velocity
  /// scale, so that a gas at rest converges), m/s.
  double velocity_floor = 1e-6;
  /// Relative residual of each iterative linear solve (of the increments, so it multiplies the
  /// current SIMPLE residual), dimensionless.
  double linear_tolerance = 1e-3;
  GasPressureSolver pressure_solver = GasPressureSolver::Automatic;  ///< See GasPressureSolver.
  int direct_cell_limit = 1000;  ///< Automatic on 3-D grids: Direct up to this many cells.
};

/// What one step did.
struct GasStepReport {
  int iterations = 0;      ///< SIMPLE iterations used.
  bool converged = false;  ///< Both measures below tolerance before max_iterations.
  /// Mass imbalance of the momentum-predicted velocities at the last iteration (the SIMPLE
  /// convergence measure), relative to the largest face volume flow, dimensionless.
  double predicted_mass_imbalance = 0.0;
  /// Largest velocity change of the last iteration over the velocity scale, dimensionless.
  double velocity_change = 0.0;
  /// Mass imbalance of the final (corrected) velocities, as mass_imbalance(), dimensionless.
  double mass_imbalance = 0.0;
};

/// Everything a GasSolver's next step depends on besides that step's inputs (for checkpoints):
/// GasSolver::set_state(state()) on a solver of the same grid and boundaries reproduces the
/// following steps bit for bit.
struct GasSolverState {
  /// Per axis, the interstitial velocity normal to each face of that axis (laid out as
  /// GasSolver::face_velocity), m/s.
  std::array<std::vector<double>, 3> face_velocity;
  std::vector<double> pressure;  ///< Per cell (x fastest, then y, then z), Pa.
  /// Per cell, the porosity of the last step (the old porosity of the next one); empty before
  /// the first step (which then has d eps/dt = 0), dimensionless.
  std::vector<double> previous_porosity;
  /// Per axis, per face: the inlet drop (GasSolver::inlet_drop; 0 off inlet faces), Pa.
  std::array<std::vector<double>, 3> inlet_drop;
};

/// The gas of one grid: face velocities and cell pressures, advanced one implicit step at a time
/// with the porosity, drag coefficient and solid velocity of each cell given by the caller.
class GasSolver {
 public:
  /// A gas at rest on `grid` (open volumes included) with the full pressure hydrostatic from the
  /// first outlet (0 without one). `boundaries`: x-, x+, y-, y+, z-, z+. `gravity`, m/s^2.
  /// Throws std::invalid_argument for periodic on one side only, a bad jet profile, an inlet
  /// without an outlet, non-positive density, negative viscosity or bad options.
  GasSolver(GasGrid grid, GasProperties gas, std::array<GasBoundary, 6> boundaries, Vec3 gravity,
            GasSolverOptions options = {});
  ~GasSolver();
  GasSolver(GasSolver&&) noexcept;
  GasSolver& operator=(GasSolver&&) noexcept;
  GasSolver(const GasSolver&) = delete;
  GasSolver& operator=(const GasSolver&) = delete;

  /// One implicit step of dt seconds. Per cell: porosity eps at the new time (0 < eps <= 1), drag
  /// coefficient beta (kg/m^3/s, >= 0, per unit of open volume: the drag force on the gas of a
  /// cell is beta (u - v_s) times its open volume) and solid velocity v_s (m/s). The porosity of
  /// the previous step is the old one (the first step has d eps/dt = 0). Throws
  /// std::invalid_argument for bad inputs and std::runtime_error if the solution diverges
  /// (non-finite velocities). Not converging within max_iterations is reported, not thrown.
  /// With a `side` thread the axes' momentum equations are solved at once (the same bits).
  GasStepReport step(double dt, std::span<const double> porosity, std::span<const double> beta,
                     std::span<const Vec3> solid_velocity, SideThread* side = nullptr);

  /// Sets a side's uniform inlet superficial velocity into the domain, m/s (used where the side
  /// has no jet profile). Throws std::invalid_argument if the side is no inlet.
  void set_inlet_velocity(int side, double superficial_velocity);
  /// Sets a side's jet profile (see GasBoundary::jet_profile), m/s; empty: uniform again.
  void set_inlet_profile(int side, std::vector<double> profile);
  /// Sets every open face that is not a boundary face to the interstitial velocity u, m/s.
  void set_uniform_velocity(const Vec3& u);

  /// Interstitial gas velocity at a cell centre (mean of the two faces per axis), m/s.
  Vec3 cell_velocity(int cell) const;
  /// Pressure gradient at a cell centre, Pa/m: per axis, the mean of the gradients at its two
  /// faces as they enter the momentum equation ((p_R - p_L) / dx; on an outlet the boundary
  /// pressure half a cell away; on an inlet, once a step has run, the gradient across the half
  /// cell from inlet_drop). On a wall face the gradient of the cell's other face is used (exact
  /// for a linear pressure), or rho_g g when that one is closed too.
  Vec3 pressure_gradient(int cell) const;
  /// On an inlet face: the pressure at the face minus that at its cell's centre after the last
  /// step, Pa, from the steady momentum of the gas in the half cell between them (the solver has
  /// no equation at the face, whose velocity is given): eps (p_face - p_c) = +-h/2 [beta (u_face
  /// - v_s) - eps rho_g g] along the face's axis (+ on a low side). 0 on other faces.
  double inlet_drop(int axis, int face) const { return inlet_drop_[axis][face]; }
  /// Pressure at a cell centre, Pa.
  double pressure(int cell) const { return pressure_[cell]; }
  /// Pressure of every cell, Pa.
  const std::vector<double>& pressure_field() const { return pressure_; }
  /// Interstitial velocity normal to each face of `axis`, m/s. Faces of axis a form an array like
  /// the cells, with n_a + 1 faces along a (n_a when periodic), face i_a lying at the low side of
  /// cell i_a.
  const std::vector<double>& face_velocity(int axis) const { return velocity_[axis]; }
  /// Number of faces of `axis` along each axis.
  std::array<int, 3> face_counts(int axis) const;
  /// Largest continuity residual of a cell, (d(eps V)/dt + net outflow), over the largest volume
  /// flow through a face (of the last step's final velocities), dimensionless.
  double mass_imbalance() const { return mass_imbalance_; }
  /// Net volume flow of gas out through side s (negative: inflow), m^3/s, last step.
  double boundary_outflow(int side) const;
  /// Rate at which gas momentum along side s's normal axis enters through side s, N:
  /// rho_g sum over its faces of eps A u^2 (negative on a high side: momentum along +axis that
  /// leaves); 0 on closed and periodic sides. With the gas's weight it is what separates the
  /// pressure drop across the grid from the force of the gas on the particles.
  double momentum_inflow(int side) const;

  /// The state the next step depends on besides its inputs (a copy).
  GasSolverState state() const;
  /// Restores a state() of a solver on the same grid and boundaries; throws
  /// std::invalid_argument naming the array when a size does not fit this grid.
  void set_state(GasSolverState state);

 private:
  /// The inputs of one step.
  struct StepInputs {
    double dt;
    std::span<const double> porosity, beta;
    std::span<const Vec3> solid_velocity;
  };

  void check_inputs(const StepInputs& in) const;
  /// Throws unless `side` (0..5) is an inlet.
  void check_inlet_side(int side) const;
  void set_fixed_faces(const StepInputs& in);
  void compute_fluxes();
  void prepare_momentum(int axis, const StepInputs& in);
  /// Zeroes the axis's momentum matrix, which assemble_momentum then fills row by row.
  void clear_momentum(int axis);
  /// The momentum equations' rows [begin, end) of the axis's unknowns (each row writes only its
  /// own entries, right side and diagonal: any split of the rows gives the same matrix).
  void assemble_momentum(int axis, std::size_t begin, std::size_t end);
  /// Solves the axis's assembled momentum equations and sets its velocities.
  void solve_momentum(int axis);
  void assemble_pressure_correction();
  double continuity_imbalance(const StepInputs& in);
  double face_porosity(int axis, int face, std::span<const double> porosity) const;
  /// Whether a face lies on an inlet side (open, with a cell on one side only).
  bool is_inlet_face(int axis, int face) const;
  /// Sets inlet_drop_ from the step's inputs and final velocities.
  void set_inlet_drops(const StepInputs& in);
  /// Gradient of p across a face as the momentum equation sees it, Pa/m; false if the face has
  /// none (fixed faces).
  bool face_pressure_gradient(int axis, int face, double& gradient) const;

  GasGrid grid_;
  GasProperties gas_;
  std::array<GasBoundary, 6> boundaries_;
  Vec3 gravity_;
  GasSolverOptions options_;
  std::unique_ptr<gas_detail::GasLayout> layout_;   ///< Faces, areas, matrix patterns (fixed).
  std::unique_ptr<gas_detail::GasWorkspace> work_;  ///< Matrices, factorisations, scratch.
  std::array<std::vector<double>, 3> velocity_;     ///< Face velocities per axis, m/s.
  std::vector<double> pressure_;                    ///< Cell pressures, Pa.
  std::vector<double> old_porosity_;                ///< Porosity of the last step.
  std::array<std::vector<double>, 3> inlet_drop_;   ///< Per face, see inlet_drop, Pa.
  bool has_old_porosity_ = false;
  double mass_imbalance_ = 0.0;
  std::array<double, 6> outflow_{};  ///< Volume flow out through each side, m^3/s.
};

}  // namespace carom
