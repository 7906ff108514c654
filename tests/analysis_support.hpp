#pragma once
/// Helpers shared by the analysis tests (mixing, local fields).
#include "scenarios/sample_grid.hpp"

namespace carom::test {

/// The unit cube [0, 1]^3 cut into nx x ny x nz sampling cells.
inline SampleGrid unit_cube_grid(int nx, int ny, int nz) {
  SampleGrid grid;
  grid.lower = Vec3::Zero();
  grid.upper = Vec3::Ones();
  grid.cells = {nx, ny, nz};
  return grid;
}

}  // namespace carom::test
