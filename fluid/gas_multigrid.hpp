#pragma once
/// Internal to the gas solver: conjugate gradients preconditioned by one aggregation-multigrid
/// V-cycle, for the pressure-correction equation on 3-D grids, where a sparse Cholesky
/// factorisation fills in too much (16 x 16 x 40 cells: 1e6 factor entries, 0.1 s per step).
///
/// Coarse levels merge the unknowns of 2 x 2 x 2 blocks of cells (not along axes down to one
/// cell, so 2-D grids coarsen in 2 x 2 blocks) - the additive-correction multigrid of
/// Hutchinson & Raithby (1986) that SIMPLE codes use - with the Galerkin coarse matrix (the sum of
/// the fine coefficients), one symmetric Gauss-Seidel sweep before and after the coarse
/// correction (so the preconditioner is symmetric), and a Cholesky solve on the coarsest level.
/// Patterns and level maps are built once; factorize() refills the values each step.
#include <Eigen/SparseCholesky>
#include <array>
#include <vector>

#include "gas_layout.hpp"

namespace carom::gas_detail {

class PressureMultigrid {
 public:
  /// Builds the levels for a matrix `pattern` whose unknown u is the cell at grid coordinates
  /// coordinates[u].
  void analyze(const SparseMatrix& pattern, const std::vector<std::array<int, 3>>& coordinates);
  /// Takes the values of `fine` (the analysed pattern) and computes the coarse levels.
  void factorize(const SparseMatrix& fine);
  /// Solves fine x = b by preconditioned conjugate gradients from x = 0 to the relative residual
  /// `tolerance`, at most `max_iterations`; returns the iterations used.
  int solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance, int max_iterations);

 private:
  struct Level {
    SparseMatrix matrix;               ///< This level's matrix (level 0: a copy of the fine one).
    Eigen::VectorXd inverse_diagonal;  ///< 1 / a_ii.
    std::vector<int> aggregate;        ///< Unknown -> unknown of the next level.
    std::vector<int> coarse_position;  ///< Value index -> value index in the next level.
    Eigen::VectorXd x, b, r;           ///< V-cycle scratch.
  };
  void cycle(std::size_t level);
  void smooth(Level& level, bool forward) const;

  std::vector<Level> levels_;
  Eigen::SimplicialLDLT<SparseMatrix> coarsest_;
  Eigen::VectorXd residual_, direction_, product_;
};

}  // namespace carom::gas_detail
