#include "scenarios/analysis/sample_grid.hpp"

#include <algorithm>
#include <stdexcept>

namespace carom {

int SampleGrid::cell_of(const Vec3& point) const {
  int index[3];
  for (int k = 0; k < 3; ++k) {
    const double x = point[k];
    if (!(x >= lower[k] && x <= upper[k])) return -1;  // also rejects NaN
    const double scaled = (x - lower[k]) / (upper[k] - lower[k]) * cells[k];
    index[k] = std::min(static_cast<int>(scaled), cells[k] - 1);  // upper face -> last cell
  }
  return index[0] + cells[0] * (index[1] + cells[1] * index[2]);
}

std::size_t SampleGrid::size() const {
  return static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
         static_cast<std::size_t>(cells[2]);
}

double SampleGrid::cell_volume() const {
  const Vec3 edge = upper - lower;
  return edge[0] / cells[0] * edge[1] / cells[1] * edge[2] / cells[2];
}

Vec3 SampleGrid::cell_centre(int cell) const {
  const int ix = cell % cells[0];
  const int iy = (cell / cells[0]) % cells[1];
  const int iz = cell / (cells[0] * cells[1]);
  const Vec3 edge = upper - lower;
  return lower + Vec3((ix + 0.5) * edge[0] / cells[0], (iy + 0.5) * edge[1] / cells[1],
                      (iz + 0.5) * edge[2] / cells[2]);
}

void SampleGrid::check() const {
  for (int k = 0; k < 3; ++k) {
    if (cells[k] < 1)
      throw std::invalid_argument("sample grid: every axis needs at least one cell");
    if (!(upper[k] > lower[k]))
      throw std::invalid_argument("sample grid: the upper corner must lie above the lower one");
  }
}

}  // namespace carom
