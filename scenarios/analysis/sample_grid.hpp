#pragma once
/// The sample cells that analysis bins particles into: an axis-aligned box split into equal
/// cells (the Lacey index in mixing.hpp, the local fields in local_fields.hpp).
#include <array>
#include <cstddef>

#include "core/vec3.hpp"

namespace carom {

/// An axis-aligned box split into cells[0] x cells[1] x cells[2] equal sample cells; cell
/// (ix, iy, iz) has the flat index ix + cells[0] (iy + cells[1] iz).
struct SampleGrid {
  Vec3 lower = Vec3::Zero();          ///< Lower corner of the sampled box, m.
  Vec3 upper = Vec3::Zero();          ///< Upper corner of the sampled box, m.
  std::array<int, 3> cells{1, 1, 1};  ///< Number of sample cells along x, y and z.

  /// Flat index of the cell holding `point`; -1 outside the box (or for a non-finite point).
  /// The box is closed: a point exactly on the upper face belongs to the last cell.
  int cell_of(const Vec3& point) const;
  /// Number of sample cells.
  std::size_t size() const;
  /// Volume of one sample cell, m^3.
  double cell_volume() const;
  /// Centre of the cell with flat index `cell`, m.
  Vec3 cell_centre(int cell) const;
  /// Throws std::invalid_argument unless every cells[k] >= 1 and upper > lower on every axis.
  void check() const;
};

}  // namespace carom
