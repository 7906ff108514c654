#pragma once
/// Helpers shared by the analysis and gas tests (mixing, dispersion, local fields, fluidized bed).
#include <cmath>
#include <vector>

#include "scenarios/analysis/sample_grid.hpp"

namespace carom::test {

/// The unit cube [0, 1]^3 cut into nx x ny x nz sampling cells.
inline SampleGrid unit_cube_grid(int nx, int ny, int nz) {
  SampleGrid grid;
  grid.lower = Vec3::Zero();
  grid.upper = Vec3::Ones();
  grid.cells = {nx, ny, nz};
  return grid;
}

/// Mean and standard deviation (1/(R-1)) of a sample.
struct Spread {
  double mean, deviation;
};
inline Spread spread_of(const std::vector<double>& values) {
  double mean = 0.0, square = 0.0;
  for (double v : values) mean += v;
  mean /= double(values.size());
  for (double v : values) square += (v - mean) * (v - mean);
  return {mean, std::sqrt(square / double(values.size() - 1))};
}

}  // namespace carom::test
