#pragma once
/// Internal to the gas solver (fluid/gas_solver.hpp): the fixed geometry of the staggered grid —
/// which cells border each face, open face areas, which faces are unknowns, face neighbours —
/// and the sparse-matrix patterns built from it once. Not public API.
#include <Eigen/SparseCore>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "gas_grid.hpp"
#include "gas_solver.hpp"

namespace carom::gas_detail {

/// Sparse matrix type of the solver (column-major, as Eigen's Cholesky wants).
using SparseMatrix = Eigen::SparseMatrix<double>;

/// Position of entry (row, col), which must be stored, in a compressed column-major matrix's
/// value array.
int entry_position(const SparseMatrix& m, int row, int col);

/// A cell's open fraction at or below this is solid (no gas), dimensionless.
inline constexpr double kClosedFraction = 1e-12;

/// Names of the six sides (x-, x+, y-, y+, z-, z+), as in scene files.
inline constexpr const char* kSideNames[6] = {"x_low",  "x_high", "y_low",
                                              "y_high", "z_low",  "z_high"};

/// Throws std::invalid_argument("gas solver: " + message).
[[noreturn]] inline void fail(const std::string& message) {
  throw std::invalid_argument("gas solver: " + message);
}

/// Throws std::invalid_argument("gas solver: " + message) unless `condition`. The message is
/// built before the call: checks made every fluid step use `if (!condition) fail(...)`.
inline void require(bool condition, const std::string& message) {
  if (!condition) fail(message);
}

/// Number of face cells on a side normal to `axis` (the product of the two other cell counts).
inline int side_face_cells(const std::array<int, 3>& cells, int axis) {
  return cells[0] * cells[1] * cells[2] / cells[axis];
}

/// Direction index of a neighbour: 2 axis + (1 if towards +axis), the same as side indices.
inline constexpr int direction(int axis, int sign) {
  return 2 * axis + (sign > 0 ? 1 : 0);
}

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
  std::array<std::vector<int>, 3> left;          ///< Cell on the low side (-1: boundary).
  std::array<std::vector<int>, 3> right;         ///< Cell on the high side (-1: boundary).
  std::array<std::vector<double>, 3> area;       ///< Open area, m^2 (0: closed).
  std::array<std::vector<int>, 3> unknown;       ///< Momentum unknown index (-1: fixed).
  std::array<std::vector<int>, 3> unknown_face;  ///< Face of each momentum unknown.
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
  /// The side (2 axis + (high side)) an open face of `axis` lies on, or -1 for a face between
  /// two cells (periodic wraps included) or a closed one.
  int boundary_side(int axis, int face) const {
    if (area[axis][face] == 0.0) return -1;
    if (left[axis][face] < 0) return 2 * axis;
    if (right[axis][face] < 0) return 2 * axis + 1;
    return -1;
  }
  /// Coordinates of a face of `axis` in its face array.
  std::array<int, 3> face_coordinates(int axis, int face) const {
    const auto& d = face_dims[axis];
    return {face % d[0], (face / d[0]) % d[1], face / (d[0] * d[1])};
  }
  /// The cell across the face of `axis` on side `sign` of a cell (-1: a boundary; the cell itself
  /// on a periodic axis of one cell), with the face itself in `face`.
  int across(int axis, int sign, int cell, int& face) const;
};

}  // namespace carom::gas_detail
