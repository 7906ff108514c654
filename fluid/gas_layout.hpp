#pragma once
/// Internal to the gas solver (fluid/gas_solver.hpp): the fixed geometry of the staggered grid —
/// which cells border each face, open face areas, which faces are unknowns, face neighbours —
/// the sparse-matrix patterns built from it once, and the solver's scratch. Not public API.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "gas_grid.hpp"
#include "gas_solver.hpp"

namespace carom::gas_detail {

/// Sparse matrix type of the solver (column-major, as Eigen's Cholesky wants).
using SparseMatrix = Eigen::SparseMatrix<double>;

/// A cell's open fraction at or below this is solid (no gas), dimensionless.
inline constexpr double kClosedFraction = 1e-12;

/// Direction index of a neighbour: 2 axis + (1 if towards +axis), the same as side indices.
inline constexpr int direction(int axis, int sign) { return 2 * axis + (sign > 0 ? 1 : 0); }

struct GasLayout {
  GasLayout(const GasGrid& grid, const std::array<GasBoundary, 6>& boundaries);

  std::array<int, 3> cells{};                     ///< Cells per axis.
  std::array<bool, 3> periodic{};                 ///< Periodic axes.
  Vec3 spacing = Vec3::Zero();                    ///< dx, dy, dz, m.
  std::array<std::array<int, 3>, 3> face_dims{};  ///< Faces of axis a along each axis.
  std::array<int, 3> face_count{};                ///< Faces of axis a in all.
  std::vector<double> open_fraction;              ///< Per cell, dimensionless.
  std::vector<double> open_volume;                ///< Per cell, m^3.

  // Per axis, per face.
  std::array<std::vector<int>, 3> left;            ///< Cell on the low side (-1: boundary).
  std::array<std::vector<int>, 3> right;           ///< Cell on the high side (-1: boundary).
  std::array<std::vector<double>, 3> area;         ///< Open area, m^2 (0: closed).
  std::array<std::vector<int>, 3> unknown;         ///< Momentum unknown index (-1: fixed).
  std::array<std::vector<int>, 3> unknown_face;    ///< Face of each momentum unknown.
  std::array<std::vector<std::array<int, 6>>, 3> neighbour;  ///< Face of the same axis per
                                                             ///< direction (-1: beyond a side).
  /// Momentum matrix of each axis: pattern, and the value position of each unknown's diagonal
  /// (slot 0) and of its neighbour in each direction (slot 1 + direction; -1 if none).
  std::array<SparseMatrix, 3> momentum_pattern;
  std::array<std::vector<std::array<int, 7>>, 3> momentum_slot;
  /// Per momentum unknown and direction: the two faces (of axis direction / 2) whose volume flows,
  /// halved, make the flow through that face of the control volume (-1: none; the same face
  /// twice on an outlet, where the control-volume face is the face itself).
  std::array<std::vector<std::array<std::array<int, 2>, 6>>, 3> convection_faces;
  /// Per cell: its faces of each axis, low and high side.
  std::array<std::vector<std::array<int, 2>>, 3> cell_faces;

  // Pressure correction: one unknown per active cell (open, connected to an unknown face, and not
  // the held cell of a region without an outlet).
  std::vector<int> active;       ///< Unknown index per cell (-1: inactive).
  std::vector<int> active_cell;  ///< Cell of each unknown.
  SparseMatrix pressure_pattern;
  std::vector<std::array<int, 7>> pressure_slot;  ///< As momentum_slot, neighbours across faces.

  /// Face of `axis` on the low side of a cell.
  int minus_face(int axis, int cell) const { return cell_faces[axis][cell][0]; }
  /// Face of `axis` on the high side of a cell.
  int plus_face(int axis, int cell) const { return cell_faces[axis][cell][1]; }
  /// Coordinates of a face of `axis` in its face array.
  std::array<int, 3> face_coordinates(int axis, int face) const {
    const auto& d = face_dims[axis];
    return {face % d[0], (face / d[0]) % d[1], face / (d[0] * d[1])};
  }
  /// The cell across the face of `axis` on side `sign` of a cell (-1: a boundary; the cell itself
  /// on a periodic axis of one cell), with the face itself in `face`.
  int across(int axis, int sign, int cell, int& face) const;
};

/// Matrices, linear solvers and scratch arrays of the SIMPLE loop.
struct GasWorkspace {
  std::array<SparseMatrix, 3> momentum;          ///< Momentum matrix per axis (layout pattern).
  std::array<Eigen::VectorXd, 3> rhs, solution;  ///< Per momentum unknown.
  std::array<std::vector<double>, 3> diagonal;   ///< Relaxed a_P / alpha_u, kg/s.
  std::array<std::vector<double>, 3> neighbour_sum;  ///< sum a_nb per unknown, kg/s.
  // Per momentum unknown, fixed within a step: a_P and b without convection, pressure and
  // relaxation; the pressure-force factor eps_f A_f; the diffusion D towards each direction.
  std::array<std::vector<double>, 3> base_diagonal;   ///< kg/s.
  std::array<std::vector<double>, 3> base_source;     ///< N.
  std::array<std::vector<double>, 3> pressure_area;   ///< eps_f A_f, m^2.
  std::array<std::vector<std::array<double, 6>>, 3> diffusion;  ///< kg/s.
  std::array<std::vector<double>, 3> face_open_area;  ///< eps_f A_f per face (step), m^2.
  std::array<std::vector<double>, 3> d;          ///< SIMPLE d = eps A / (a_P / alpha_u), m^3/(N s).
  std::array<std::vector<double>, 3> flux;       ///< Volume flow eps u A per face, m^3/s.
  std::array<std::vector<double>, 3> old_velocity;  ///< u at the start of the step, m/s.
  std::array<std::vector<double>, 3> iterate;       ///< u at the start of the iteration, m/s.
  SparseMatrix pressure;  ///< Pressure-correction matrix (layout pattern).
  Eigen::VectorXd pressure_rhs, correction;
  std::vector<double> residual;      ///< Continuity residual per cell, m^3/s.
  std::vector<double> old_porosity;  ///< eps at the start of the step.
  bool use_direct = true;
  Eigen::SimplicialLDLT<SparseMatrix> direct;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper,
                           Eigen::IncompleteCholesky<double>>
      iterative;
  Eigen::BiCGSTAB<SparseMatrix, Eigen::DiagonalPreconditioner<double>> momentum_solver;
};

}  // namespace carom::gas_detail
