#pragma once
/// Porosity mapping (core/DESIGN.md, "The gas and the two time scales"): each particle's volume is
/// split over the gas cells it overlaps by exact sphere-cell volumes (fluid/overlap.hpp), each
/// cell's open volume is the part inside the walls, and eps_c = 1 - solid_c / open_c. The split
/// weights double as the interpolation weights of cell quantities to the particle, so the drag
/// reaction on the gas is exactly minus the drag on the particles and the mapped solid volume is
/// the particles' volume.
#include <array>
#include <span>
#include <vector>

#include "core/domain.hpp"
#include "core/vec3.hpp"
#include "core/wall.hpp"

namespace carom {

/// A regular grid of nx x ny x nz cells over the box [lower, upper]; cell (i, j, k) has index
/// i + nx (j + ny k) (x fastest).
struct CellLayout {
  Vec3 lower = Vec3::Zero();          ///< Lower corner of the grid, m.
  Vec3 upper = Vec3::Ones();          ///< Upper corner of the grid, m.
  std::array<int, 3> cells{1, 1, 1};  ///< Cells per axis.

  /// The grid over a domain's box.
  static CellLayout over(const Domain& domain, const std::array<int, 3>& cells) {
    return CellLayout{domain.lower, domain.upper, cells};
  }
  /// Cell edge lengths, m.
  Vec3 cell_size() const {
    return (upper - lower).cwiseQuotient(Vec3(cells[0], cells[1], cells[2]));
  }
  /// Volume of one cell, m^3.
  double cell_volume() const { return cell_size().prod(); }
  /// Number of cells.
  int count() const { return cells[0] * cells[1] * cells[2]; }
  /// Index of cell (i, j, k).
  int index(int i, int j, int k) const { return i + cells[0] * (j + cells[1] * k); }
};

/// The share of one particle's volume in one cell.
struct CellShare {
  int cell = 0;         ///< Cell index (CellLayout::index).
  double fraction = 0;  ///< Fraction of the particle's volume in that cell (shares sum to 1).
};

/// Appends to `shares` the cells overlapped by the sphere (centre, radius) and the fraction of
/// its volume in each (exact volumes, normalised so that the fractions sum to 1 to round-off,
/// about 1e-15). Periodic axes wrap; on a walled axis the part of a sphere poking out of the
/// grid (by round-off) counts in the boundary cell. A sphere inside one cell costs a few
/// comparisons, one across a single face two exact ball-corner volumes; otherwise it costs one
/// per grid node inside its bounding box.
void split_sphere(const CellLayout& layout, const std::array<bool, 3>& periodic, const Vec3& centre,
                  double radius, std::vector<CellShare>& shares);
namespace detail {
/// split_sphere without its shortcut for a sphere across one face (every node's ball-corner
/// volume, each cell's by inclusion-exclusion): the oracle the shortcut gives the same bits as.
void split_sphere_by_corners(const CellLayout& layout, const std::array<bool, 3>& periodic,
                             const Vec3& centre, double radius, std::vector<CellShare>& shares);
}  // namespace detail
/// Same, returning the shares (allocates; prefer the appending form in loops).
std::vector<CellShare> split_sphere(const CellLayout& layout, const std::array<bool, 3>& periodic,
                                    const Vec3& centre, double radius);

/// Volume of each cell inside all the walls (planes: the side their normal points to; cylinder
/// and cone: the inside), m^3; how each shape cuts a cell is in wall_cell_cut.hpp. Exact for
/// cells cut by any planes (axis-aligned ones clip the cell, others by convex clipping) or by one
/// cylinder plus axis-aligned planes; to about 1e-13 of the cell volume for one cone plus
/// axis-aligned planes (quadrature over z of the exact cross-section); a cell cut both by a
/// curved wall and by an oblique plane, or by two curved walls, gets the product of the inside
/// fractions.
std::vector<double> open_volume(const CellLayout& layout, const std::vector<Wall>& walls);

/// Solid volume and porosity of every cell.
struct SolidMapping {
  std::vector<double> solid_volume;  ///< Sum over particles of fraction x particle volume, m^3.
  std::vector<double> porosity;      ///< eps = max(min_porosity, 1 - solid / open); 1 if open = 0.
  int floored_cells = 0;             ///< Cells where 1 - solid / open fell below min_porosity.
};

/// Maps the particles' volumes to the cells and computes the porosity. A particle inside the
/// walls only overlaps open volume, so solid <= open up to overlaps and round-off, which the
/// floor `min_porosity` absorbs (a cell with a sliver of open volume can be floored); a cell
/// with no open volume (outside the walls) gets eps = 1 and no solid.
SolidMapping map_solid_volume(const CellLayout& layout, const std::array<bool, 3>& periodic,
                              std::span<const Vec3> centres, std::span<const double> radii,
                              const std::vector<double>& open_volume, double min_porosity = 0.3);

}  // namespace carom
