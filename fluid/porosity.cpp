#include "porosity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "overlap.hpp"
#include "wall_cell_cut.hpp"

namespace carom {

namespace {
/// i modulo n in [0, n): a branch where i is inside already (a sphere's cells nearly always are:
/// the integer division cost more than the rest of a one-cell split).
int wrap(int i, int n) {
  if (i >= 0 && i < n) return i;
  const int m = i % n;
  return m < 0 ? m + n : m;
}

/// The cells a sphere spans along one axis and the cell faces relative to its centre.
struct AxisSpan {
  int first = 0;              ///< First cell (before wrapping).
  int count = 1;              ///< Cells spanned.
  std::vector<double> edges;  ///< count + 1 face positions minus the centre, clamped to [-r, r].
};

/// The first and last cell a sphere spans along axis k (h: the cell length).
void span_cells(const CellLayout& layout, bool periodic, int k, double h, double centre,
                double radius, AxisSpan& span) {
  const int n = layout.cells[k];
  int first = static_cast<int>(std::floor((centre - radius - layout.lower[k]) / h));
  int last = static_cast<int>(std::ceil((centre + radius - layout.lower[k]) / h)) - 1;
  last = std::max(last, first);
  if (!periodic) {
    first = std::clamp(first, 0, n - 1);
    last = std::clamp(last, 0, n - 1);
  }
  span.first = first;
  span.count = last - first + 1;
}

/// The faces of the cells span_cells found, relative to the centre.
void span_edges(const CellLayout& layout, bool periodic, int k, double h, double centre,
                double radius, AxisSpan& span) {
  const int n = layout.cells[k], first = span.first, last = first + span.count - 1;
  span.edges.resize(span.count + 1);
  for (int j = 0; j <= span.count; ++j)
    span.edges[j] = std::clamp(layout.lower[k] + (first + j) * h - centre, -radius, radius);
  // Walled axis: what pokes out of the grid counts in the boundary cell.
  if (!periodic && first == 0) span.edges.front() = -radius;
  if (!periodic && last == n - 1) span.edges.back() = radius;
}
}  // namespace

namespace {
/// The axis along which a sphere spans two cells when it spans one along the others, and every
/// face beyond it lies at or past its far side (so every node's ball-corner volume but two is 0
/// exactly: ball_corner_volume's first test); -1 otherwise.
int across_one_face(const std::array<AxisSpan, 3>& span, double radius) {
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (span[k].count == 2 && axis < 0)
      axis = k;
    else if (span[k].count != 1)
      return -1;
  }
  if (axis < 0) return -1;
  for (int k = 0; k < 3; ++k)
    if (span[k].edges.back() < radius) return -1;
  return axis;
}

/// The cells a sphere spans along each axis (span_cells), and whether that is one cell.
bool spans_one_cell(const CellLayout& layout, const std::array<bool, 3>& periodic,
                    const Vec3& centre, double radius, std::array<AxisSpan, 3>& span) {
  const Vec3 h = layout.cell_size();
  for (int k = 0; k < 3; ++k) span_cells(layout, periodic[k], k, h[k], centre[k], radius, span[k]);
  return (span[0].count == 1 && span[1].count == 1 && span[2].count == 1) || radius <= 0.0;
}

/// The index of the cell at (p, q, s) from the first cell the sphere spans, wrapped.
int spanned_cell(const CellLayout& layout, const std::array<AxisSpan, 3>& span, int p, int q,
                 int s) {
  return layout.index(wrap(span[0].first + p, layout.cells[0]),
                      wrap(span[1].first + q, layout.cells[1]),
                      wrap(span[2].first + s, layout.cells[2]));
}

/// The shares of a sphere that spans more than one cell, with the shortcut for a sphere across
/// one face (`shortcut`) or by every node.
void split_spanning(const CellLayout& layout, const std::array<bool, 3>& periodic,
                    const Vec3& centre, double radius, std::array<AxisSpan, 3>& span,
                    std::vector<CellShare>& shares, bool shortcut) {
  thread_local std::vector<double> corner;
  const Vec3 h = layout.cell_size();
  for (int k = 0; k < 3; ++k) span_edges(layout, periodic[k], k, h[k], centre[k], radius, span[k]);
  const int mx = span[0].count, my = span[1].count, mz = span[2].count;
  const std::size_t start = shares.size();
  double total = 0.0;
  auto add = [&](int p, int q, int s, double volume) {
    if (volume <= 0.0) return;
    shares.push_back({spanned_cell(layout, span, p, q, s), volume});
    total += volume;
  };
  if (const int k = shortcut ? across_one_face(span, radius) : -1; k >= 0) {
    // A sphere across one face (the commonest split): the two nodes on the near faces of the
    // other axes. Of the eight terms below the others are +0 exactly, so the two volumes are
    // the same bits: near - middle for the first cell, middle for the second.
    std::array<double, 3> node{span[0].edges[0], span[1].edges[0], span[2].edges[0]};
    const double near = ball_corner_volume(node[0], node[1], node[2], radius);
    node[k] = span[k].edges[1];
    const double middle = ball_corner_volume(node[0], node[1], node[2], radius);
    std::array<int, 3> second{0, 0, 0};
    second[k] = 1;
    add(0, 0, 0, near - middle);
    add(second[0], second[1], second[2], middle);
  } else {
    // Ball-corner volumes at the grid nodes; each cell's volume by inclusion-exclusion.
    const int sx = mx + 1, sy = my + 1;
    corner.resize(static_cast<std::size_t>(sx) * sy * (mz + 1));
    for (int s = 0; s <= mz; ++s)
      for (int q = 0; q <= my; ++q)
        for (int p = 0; p <= mx; ++p)
          corner[p + sx * (q + sy * s)] =
              ball_corner_volume(span[0].edges[p], span[1].edges[q], span[2].edges[s], radius);
    auto at = [&](int p, int q, int s) { return corner[p + sx * (q + sy * s)]; };
    for (int s = 0; s < mz; ++s)
      for (int q = 0; q < my; ++q)
        for (int p = 0; p < mx; ++p)
          add(p, q, s,
              at(p, q, s) - at(p + 1, q, s) - at(p, q + 1, s) - at(p, q, s + 1) +
                  at(p + 1, q + 1, s) + at(p + 1, q, s + 1) + at(p, q + 1, s + 1) -
                  at(p + 1, q + 1, s + 1));
  }
  for (std::size_t i = start; i < shares.size(); ++i) shares[i].fraction /= total;
  // A sphere wider than a periodic box overlaps some cells through several images: merge them.
  const std::array<int, 3>& n = layout.cells;
  if ((periodic[0] && mx > n[0]) || (periodic[1] && my > n[1]) || (periodic[2] && mz > n[2])) {
    std::sort(shares.begin() + start, shares.end(),
              [](const CellShare& a, const CellShare& b) { return a.cell < b.cell; });
    std::size_t out = start;
    for (std::size_t i = start; i < shares.size(); ++i) {
      if (out > start && shares[out - 1].cell == shares[i].cell)
        shares[out - 1].fraction += shares[i].fraction;
      else
        shares[out++] = shares[i];
    }
    shares.resize(out);
  }
}
}  // namespace

void split_sphere(const CellLayout& layout, const std::array<bool, 3>& periodic, const Vec3& centre,
                  double radius, std::vector<CellShare>& shares) {
  thread_local std::array<AxisSpan, 3> span;
  if (spans_one_cell(layout, periodic, centre, radius, span))
    shares.push_back({spanned_cell(layout, span, 0, 0, 0), 1.0});
  else
    split_spanning(layout, periodic, centre, radius, span, shares, true);
}

void detail::split_sphere_by_corners(const CellLayout& layout, const std::array<bool, 3>& periodic,
                                     const Vec3& centre, double radius,
                                     std::vector<CellShare>& shares) {
  thread_local std::array<AxisSpan, 3> span;
  if (spans_one_cell(layout, periodic, centre, radius, span))
    shares.push_back({spanned_cell(layout, span, 0, 0, 0), 1.0});
  else
    split_spanning(layout, periodic, centre, radius, span, shares, false);
}

std::vector<CellShare> split_sphere(const CellLayout& layout, const std::array<bool, 3>& periodic,
                                    const Vec3& centre, double radius) {
  std::vector<CellShare> shares;
  split_sphere(layout, periodic, centre, radius, shares);
  return shares;
}

std::vector<double> open_volume(const CellLayout& layout, const std::vector<Wall>& walls) {
  const Vec3 size = layout.cell_size();
  std::vector<double> open(layout.count(), 0.0);
  CellCut cell;
  for (int k = 0; k < layout.cells[2]; ++k)
    for (int j = 0; j < layout.cells[1]; ++j)
      for (int i = 0; i < layout.cells[0]; ++i) {
        cell.lower = layout.lower + Vec3(i, j, k).cwiseProduct(size);
        cell.upper = cell.lower + size;
        if (i == layout.cells[0] - 1) cell.upper.x() = layout.upper.x();
        if (j == layout.cells[1] - 1) cell.upper.y() = layout.upper.y();
        if (k == layout.cells[2] - 1) cell.upper.z() = layout.upper.z();
        cell.cutting.clear();
        cell.outside = false;
        for (const Wall& wall : walls)
          std::visit([&](const auto& shape) { clip_cell(shape, cell); }, wall.shape);
        if ((cell.upper.array() <= cell.lower.array()).any()) continue;
        double volume = (cell.upper - cell.lower).prod();
        for (std::size_t w = 0; w < walls.size() && !cell.outside; ++w)
          std::visit([&](const auto& shape) { cut_cell(shape, cell); }, walls[w].shape);
        if (cell.outside) continue;
        if (!cell.cutting.empty())
          volume = box_halfspaces_volume(cell.lower, cell.upper, cell.cutting);
        for (const Wall& wall : walls)
          volume *= std::visit([&](const auto& shape) { return inside_fraction(shape, cell); },
                               wall.shape);
        open[layout.index(i, j, k)] = volume;
      }
  return open;
}

SolidMapping map_solid_volume(const CellLayout& layout, const std::array<bool, 3>& periodic,
                              std::span<const Vec3> centres, std::span<const double> radii,
                              const std::vector<double>& open_volume, double min_porosity) {
  const std::size_t cells = static_cast<std::size_t>(layout.count());
  SolidMapping mapping;
  mapping.solid_volume.assign(cells, 0.0);
  mapping.porosity.assign(cells, 1.0);
  std::vector<CellShare> shares;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const double a = radii[i];
    const double volume = 4.0 / 3.0 * std::numbers::pi * a * a * a;
    shares.clear();
    split_sphere(layout, periodic, centres[i], a, shares);
    for (const CellShare& s : shares) mapping.solid_volume[s.cell] += s.fraction * volume;
  }
  for (std::size_t c = 0; c < cells; ++c) {
    if (open_volume[c] <= 0.0) continue;
    const double eps = 1.0 - mapping.solid_volume[c] / open_volume[c];
    if (eps < min_porosity) ++mapping.floored_cells;
    mapping.porosity[c] = std::max(min_porosity, eps);
  }
  return mapping;
}

}  // namespace carom
