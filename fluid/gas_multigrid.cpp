#include "gas_multigrid.hpp"

#include <algorithm>
#include <cassert>

namespace carom::gas_detail {

namespace {

/// Levels stop coarsening at this many unknowns (then a Cholesky solve is cheap).
constexpr int kCoarsestUnknowns = 256;

}  // namespace

void PressureMultigrid::analyze(const SparseMatrix& pattern,
                                const std::vector<std::array<int, 3>>& coordinates) {
  levels_.clear();
  levels_.emplace_back();
  levels_.back().matrix = pattern;
  std::vector<std::array<int, 3>> coords = coordinates;
  while (static_cast<int>(coords.size()) > kCoarsestUnknowns) {
    Level& level = levels_.back();
    const int n = static_cast<int>(coords.size());
    std::array<int, 3> dims{1, 1, 1};
    for (const auto& c : coords)
      for (int a = 0; a < 3; ++a) dims[a] = std::max(dims[a], c[a] + 1);
    std::array<int, 3> coarse_dims;
    for (int a = 0; a < 3; ++a) coarse_dims[a] = dims[a] > 1 ? (dims[a] + 1) / 2 : 1;
    // Aggregates: the blocks that hold at least one unknown, numbered as first met.
    std::vector<int> block_id(
        static_cast<std::size_t>(coarse_dims[0]) * coarse_dims[1] * coarse_dims[2], -1);
    std::vector<std::array<int, 3>> coarse_coords;
    level.aggregate.resize(n);
    for (int u = 0; u < n; ++u) {
      std::array<int, 3> c;
      for (int a = 0; a < 3; ++a) c[a] = dims[a] > 1 ? coords[u][a] / 2 : coords[u][a];
      const std::size_t block = c[0] + static_cast<std::size_t>(coarse_dims[0]) *
                                           (c[1] + static_cast<std::size_t>(coarse_dims[1]) * c[2]);
      if (block_id[block] < 0) {
        block_id[block] = static_cast<int>(coarse_coords.size());
        coarse_coords.push_back(c);
      }
      level.aggregate[u] = block_id[block];
    }
    const int m = static_cast<int>(coarse_coords.size());
    if (m == n) {
      level.aggregate.clear();
      break;
    }
    // Galerkin pattern: entry (i, j) adds to (aggregate i, aggregate j).
    const int* outer = level.matrix.outerIndexPtr();
    const int* inner = level.matrix.innerIndexPtr();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(level.matrix.nonZeros());
    for (int col = 0; col < n; ++col)
      for (int k = outer[col]; k < outer[col + 1]; ++k)
        entries.emplace_back(level.aggregate[inner[k]], level.aggregate[col], 0.0);
    SparseMatrix coarse(m, m);
    coarse.setFromTriplets(entries.begin(), entries.end());
    coarse.makeCompressed();
    level.coarse_position.resize(level.matrix.nonZeros());
    for (int col = 0; col < n; ++col)
      for (int k = outer[col]; k < outer[col + 1]; ++k)
        level.coarse_position[k] =
            entry_position(coarse, level.aggregate[inner[k]], level.aggregate[col]);
    levels_.emplace_back();
    levels_.back().matrix = std::move(coarse);
    coords = std::move(coarse_coords);
  }
  for (Level& level : levels_) {
    const auto n = level.matrix.rows();
    level.inverse_diagonal.setZero(n);
    level.x.setZero(n);
    level.b.setZero(n);
    level.r.setZero(n);
  }
  coarsest_.analyzePattern(levels_.back().matrix);
}

void PressureMultigrid::factorize(const SparseMatrix& fine) {
  SparseMatrix& top = levels_.front().matrix;
  assert(fine.nonZeros() == top.nonZeros());
  std::copy(fine.valuePtr(), fine.valuePtr() + fine.nonZeros(), top.valuePtr());
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Level& level = levels_[l];
    const double* values = level.matrix.valuePtr();
    for (int col = 0; col < level.matrix.cols(); ++col)
      level.inverse_diagonal[col] = 1.0 / level.matrix.coeff(col, col);
    if (l + 1 == levels_.size()) break;
    SparseMatrix& next = levels_[l + 1].matrix;
    double* coarse = next.valuePtr();
    std::fill(coarse, coarse + next.nonZeros(), 0.0);
    for (std::size_t k = 0; k < level.coarse_position.size(); ++k)
      coarse[level.coarse_position[k]] += values[k];
  }
  coarsest_.factorize(levels_.back().matrix);
}

void PressureMultigrid::smooth(Level& level, bool forward) const {
  // Gauss-Seidel; the matrix is symmetric, so column i holds row i.
  const SparseMatrix& a = level.matrix;
  const int n = static_cast<int>(a.cols());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* values = a.valuePtr();
  for (int step = 0; step < n; ++step) {
    const int i = forward ? step : n - 1 - step;
    double sum = level.b[i];
    for (int k = outer[i]; k < outer[i + 1]; ++k)
      if (inner[k] != i) sum -= values[k] * level.x[inner[k]];
    level.x[i] = sum * level.inverse_diagonal[i];
  }
}

void PressureMultigrid::cycle(std::size_t l) {
  Level& level = levels_[l];
  if (l + 1 == levels_.size()) {
    level.x = coarsest_.solve(level.b);
    return;
  }
  level.x.setZero();
  smooth(level, true);
  level.r.noalias() = level.b - level.matrix * level.x;
  Level& next = levels_[l + 1];
  next.b.setZero();
  for (std::size_t u = 0; u < level.aggregate.size(); ++u) next.b[level.aggregate[u]] += level.r[u];
  cycle(l + 1);
  for (std::size_t u = 0; u < level.aggregate.size(); ++u) level.x[u] += next.x[level.aggregate[u]];
  smooth(level, false);
}

int PressureMultigrid::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                             int max_iterations) {
  const SparseMatrix& a = levels_.front().matrix;
  x.setZero(b.size());
  const double target = tolerance * b.norm();
  if (target == 0.0) return 0;
  residual_ = b;
  Level& top = levels_.front();
  top.b = residual_;
  cycle(0);
  direction_ = top.x;
  double rz = residual_.dot(top.x);
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    product_.noalias() = a * direction_;
    const double step = rz / direction_.dot(product_);
    x += step * direction_;
    residual_ -= step * product_;
    if (residual_.norm() <= target) return iteration;
    top.b = residual_;
    cycle(0);
    const double rz_next = residual_.dot(top.x);
    direction_ = top.x + (rz_next / rz) * direction_;
    rz = rz_next;
  }
  return max_iterations;
}

}  // namespace carom::gas_detail
