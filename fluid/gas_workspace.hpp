#pragma once
/// Internal to the gas solver (fluid/gas_solver.hpp): matrices, linear solvers and scratch arrays
/// of the SIMPLE loop. Not public API.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <array>
#include <vector>

#include "gas_layout.hpp"
#include "gas_multigrid.hpp"

namespace carom::gas_detail {

/// Matrices, linear solvers and scratch arrays of the SIMPLE loop.
struct GasWorkspace {
  std::array<SparseMatrix, 3> momentum;              ///< Momentum matrix per axis (layout pattern).
  std::array<Eigen::VectorXd, 3> rhs, solution;      ///< Per momentum unknown.
  std::array<std::vector<double>, 3> diagonal;       ///< Relaxed a_P / alpha_u, kg/s.
  std::array<std::vector<double>, 3> neighbour_sum;  ///< sum a_nb per unknown, kg/s.
  // Per momentum unknown, fixed within a step: a_P and b without convection, pressure and
  // relaxation; the pressure-force factor eps_f A_f; the diffusion D towards each direction.
  std::array<std::vector<double>, 3> base_diagonal;             ///< kg/s.
  std::array<std::vector<double>, 3> base_source;               ///< N.
  std::array<std::vector<double>, 3> pressure_area;             ///< eps_f A_f, m^2.
  std::array<std::vector<std::array<double, 6>>, 3> diffusion;  ///< kg/s.
  std::array<std::vector<double>, 3> face_porosity;             ///< eps_f per face (step).
  std::array<std::vector<double>, 3> flow_area;                 ///< eps_f A_f per face (step), m^2.
  std::array<std::vector<double>, 3> d;     ///< SIMPLE d = eps A / (a_P / alpha_u), m^3/(N s).
  std::array<std::vector<double>, 3> flux;  ///< Volume flow eps u A per face, m^3/s.
  std::array<std::vector<double>, 3> old_velocity;  ///< u at the start of the step, m/s.
  std::array<std::vector<double>, 3> iterate;       ///< u at the start of the iteration, m/s.
  SparseMatrix pressure;  ///< Pressure-correction matrix (layout pattern).
  Eigen::VectorXd pressure_rhs, correction;
  std::vector<double> residual;      ///< Continuity residual per cell, m^3/s.
  std::vector<double> old_porosity;  ///< eps at the start of the step.
  bool use_direct = true;
  Eigen::SimplicialLDLT<SparseMatrix> direct;
  PressureMultigrid multigrid;
  /// One per axis: the axes' momentum equations may be solved at once (GasSolver::step).
  std::array<Eigen::BiCGSTAB<SparseMatrix, Eigen::DiagonalPreconditioner<double>>, 3>
      momentum_solver;
};

}  // namespace carom::gas_detail
