#pragma once
/// The gas grid (core/DESIGN.md, "The gas and the two time scales"): a regular nx x ny x nz box of
/// cells, each with the volume open to the gas (cells cut by a cylinder wall hold less).
/// Cell (i, j, k) has index i + nx (j + ny k) (x fastest), as fluid/porosity.hpp's CellLayout.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace carom {

class GasGrid {
 public:
  /// A grid of cells[0] x cells[1] x cells[2] cells over the box [lower, upper] (m), every cell
  /// fully open. Throws std::invalid_argument for a count below 1 or an empty box.
  GasGrid(const Vec3& lower, const Vec3& upper, const std::array<int, 3>& cells)
      : lower_(lower), upper_(upper), cells_(cells) {
    static const char* const kAxis[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      if (cells[a] < 1)
        throw std::invalid_argument(std::string("gas grid: ") + std::to_string(cells[a]) +
                                    " cells along " + kAxis[a] +
                                    "; every axis needs at least 1 cell (use 1 for a 1-D or "
                                    "2-D grid)");
      if (!std::isfinite(lower[a]) || !std::isfinite(upper[a]) || !(upper[a] > lower[a]))
        throw std::invalid_argument(std::string("gas grid: the box is empty or not finite along ") +
                                    kAxis[a] + " (lower " + std::to_string(lower[a]) +
                                    " m, upper " + std::to_string(upper[a]) +
                                    " m); upper must exceed lower");
    }
    if (static_cast<double>(cells[0]) * cells[1] * cells[2] > 1e8)
      throw std::invalid_argument("gas grid: more than 1e8 cells; use a coarser grid");
    open_volume_.assign(count(), cell_volume());
  }

  /// Lower corner of the grid, m.
  const Vec3& lower() const { return lower_; }
  /// Upper corner of the grid, m.
  const Vec3& upper() const { return upper_; }
  /// Cells per axis.
  const std::array<int, 3>& cells() const { return cells_; }
  /// Number of cells.
  int count() const { return cells_[0] * cells_[1] * cells_[2]; }
  /// Cell edge lengths (dx, dy, dz), m.
  Vec3 spacing() const {
    return (upper_ - lower_).cwiseQuotient(Vec3(cells_[0], cells_[1], cells_[2]));
  }
  /// Full volume of one cell dx dy dz, m^3.
  double cell_volume() const { return spacing().prod(); }
  /// Full area of one cell face normal to `axis` (dy dz for x), m^2.
  double face_area(int axis) const { return cell_volume() / spacing()[axis]; }
  /// Index of cell (i, j, k).
  int index(int i, int j, int k) const { return i + cells_[0] * (j + cells_[1] * k); }
  /// Index of cell (i, j, k) given as an array.
  int index(const std::array<int, 3>& ijk) const { return index(ijk[0], ijk[1], ijk[2]); }
  /// (i, j, k) of a cell index.
  std::array<int, 3> coordinates(int cell) const {
    return {cell % cells_[0], (cell / cells_[0]) % cells_[1], cell / (cells_[0] * cells_[1])};
  }
  /// Centre of a cell, m.
  Vec3 centre(int cell) const {
    const auto ijk = coordinates(cell);
    return lower_ + spacing().cwiseProduct(Vec3(ijk[0] + 0.5, ijk[1] + 0.5, ijk[2] + 0.5));
  }

  /// Volume of each cell open to the gas (inside the walls), m^3; all full cells by default.
  const std::vector<double>& open_volume() const { return open_volume_; }
  /// Sets the open volume of every cell (m^3, one per cell, 0 <= v <= cell volume; a cell with
  /// no open volume is solid and takes no part in the flow). Throws std::invalid_argument.
  void set_open_volume(std::vector<double> open_volume) {
    if (open_volume.size() != static_cast<std::size_t>(count()))
      throw std::invalid_argument("gas grid: open volume given for " +
                                  std::to_string(open_volume.size()) + " cells, the grid has " +
                                  std::to_string(count()));
    const double full = cell_volume();
    for (std::size_t c = 0; c < open_volume.size(); ++c) {
      if (!(open_volume[c] >= 0.0 && open_volume[c] <= full * (1.0 + 1e-9)))
        throw std::invalid_argument("gas grid: open volume " + std::to_string(open_volume[c]) +
                                    " m^3 of cell " + std::to_string(c) + " is outside [0, " +
                                    std::to_string(full) + "] (the cell volume)");
      open_volume[c] = std::min(open_volume[c], full);
    }
    open_volume_ = std::move(open_volume);
  }
  /// Open volume over full volume of a cell, dimensionless in [0, 1].
  double open_fraction(int cell) const { return open_volume_[cell] / cell_volume(); }

 private:
  Vec3 lower_;
  Vec3 upper_;
  std::array<int, 3> cells_;
  std::vector<double> open_volume_;
};

}  // namespace carom
