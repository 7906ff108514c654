#include "gas_layout.hpp"

#include <algorithm>
#include <cassert>
#include <queue>

namespace carom::gas_detail {

int entry_position(const SparseMatrix& m, int row, int col) {
  const int* inner = m.innerIndexPtr();
  const int begin = m.outerIndexPtr()[col], end = m.outerIndexPtr()[col + 1];
  const int* found = std::lower_bound(inner + begin, inner + end, row);
  assert(found != inner + end && *found == row);
  return static_cast<int>(found - inner);
}

namespace {

using Triplet = Eigen::Triplet<double>;

/// A compressed n x n matrix with the given entries (values 0).
SparseMatrix pattern(int n, const std::vector<Triplet>& entries) {
  SparseMatrix m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

}  // namespace

GasLayout::GasLayout(const GasGrid& grid, const std::array<GasBoundary, 6>& boundaries) {
  cells = grid.cells();
  spacing = grid.spacing();
  const int cell_count = grid.count();
  open_volume = grid.open_volume();
  open_fraction.resize(cell_count);
  for (int c = 0; c < cell_count; ++c) open_fraction[c] = grid.open_fraction(c);
  for (int a = 0; a < 3; ++a) {
    periodic[a] = boundaries[2 * a].kind == GasBoundaryKind::Periodic;
    face_dims[a] = cells;
    face_dims[a][a] = cells[a] + (periodic[a] ? 0 : 1);
    face_count[a] = face_dims[a][0] * face_dims[a][1] * face_dims[a][2];
  }

  for (int a = 0; a < 3; ++a) {
    cell_faces[a].resize(cell_count);
    const auto& d = face_dims[a];
    for (int c = 0; c < cell_count; ++c) {
      auto ijk = grid.coordinates(c);
      cell_faces[a][c][0] = ijk[0] + d[0] * (ijk[1] + d[1] * ijk[2]);
      ijk[a] += 1;
      if (periodic[a]) ijk[a] %= cells[a];
      cell_faces[a][c][1] = ijk[0] + d[0] * (ijk[1] + d[1] * ijk[2]);
    }
  }

  for (int a = 0; a < 3; ++a) {
    const int n = face_count[a];
    left[a].assign(n, -1);
    right[a].assign(n, -1);
    area[a].assign(n, 0.0);
    unknown[a].assign(n, -1);
    neighbour[a].assign(n, {-1, -1, -1, -1, -1, -1});
    unknown_face[a].clear();
    for (int f = 0; f < n; ++f) {
      const auto ijk = face_coordinates(a, f);
      // The cells on both sides.
      auto low = ijk, high = ijk;
      low[a] -= 1;
      if (low[a] < 0 && periodic[a]) low[a] = cells[a] - 1;
      if (low[a] >= 0) left[a][f] = grid.index(low);
      if (high[a] < cells[a]) right[a][f] = grid.index(high);
      // Open area: the smaller open fraction of the cells on both sides.
      double fraction = 1.0;
      if (left[a][f] >= 0) fraction = std::min(fraction, open_fraction[left[a][f]]);
      if (right[a][f] >= 0) fraction = std::min(fraction, open_fraction[right[a][f]]);
      if (fraction > kClosedFraction) area[a][f] = fraction * grid.face_area(a);
      // Neighbouring faces of the same axis.
      for (int b = 0; b < 3; ++b) {
        for (int sign : {-1, 1}) {
          auto other = ijk;
          other[b] += sign;
          const int limit = face_dims[a][b];
          if (periodic[b]) {
            other[b] = (other[b] + limit) % limit;
          } else if (other[b] < 0 || other[b] >= limit) {
            continue;
          }
          neighbour[a][f][direction(b, sign)] =
              other[0] + face_dims[a][0] * (other[1] + face_dims[a][1] * other[2]);
        }
      }
      // An unknown: open, and between two cells or on an outlet.
      const bool inside = left[a][f] >= 0 && right[a][f] >= 0;
      const int side = left[a][f] < 0 ? 2 * a : 2 * a + 1;
      if (area[a][f] > 0.0 && (inside || boundaries[side].kind == GasBoundaryKind::Outlet)) {
        unknown[a][f] = static_cast<int>(unknown_face[a].size());
        unknown_face[a].push_back(f);
      }
    }
    // Momentum pattern: each unknown couples to its unknown neighbours.
    const int m = static_cast<int>(unknown_face[a].size());
    std::vector<Triplet> entries;
    entries.reserve(7 * m);
    for (int u = 0; u < m; ++u) {
      entries.emplace_back(u, u, 0.0);
      for (int g : neighbour[a][unknown_face[a][u]])
        if (g >= 0 && unknown[a][g] >= 0) entries.emplace_back(u, unknown[a][g], 0.0);
    }
    momentum_pattern[a] = pattern(m, entries);
    // Convection through the control-volume faces: along a, the faces at the centres of R and
    // L (mean of the two a-faces of that cell; the face itself on an outlet); across b, the
    // b-faces of L and R on that side.
    convection_faces[a].assign(m, {});
    for (int u = 0; u < m; ++u) {
      const int f = unknown_face[a][u];
      for (int b = 0; b < 3; ++b)
        for (int sign : {-1, 1}) {
          auto& faces = convection_faces[a][u][direction(b, sign)];
          if (b == a) {
            const int cell = sign > 0 ? right[a][f] : left[a][f];
            faces = {f, cell < 0 ? f : cell_faces[a][cell][sign > 0 ? 1 : 0]};
          } else {
            faces = {-1, -1};
            for (int side = 0; side < 2; ++side) {
              const int cell = side == 0 ? left[a][f] : right[a][f];
              if (cell >= 0) faces[side] = cell_faces[b][cell][sign > 0 ? 1 : 0];
            }
          }
        }
    }
    momentum_slot[a].assign(m, {-1, -1, -1, -1, -1, -1, -1});
    for (int u = 0; u < m; ++u) {
      momentum_slot[a][u][0] = entry_position(momentum_pattern[a], u, u);
      for (int dir = 0; dir < 6; ++dir) {
        const int g = neighbour[a][unknown_face[a][u]][dir];
        if (g >= 0 && unknown[a][g] >= 0)
          momentum_slot[a][u][1 + dir] = entry_position(momentum_pattern[a], u, unknown[a][g]);
      }
    }
  }

  // Pressure unknowns: open cells with an unknown face to another cell or an outlet. Regions of
  // cells connected through unknown faces without an outlet get their first cell held.
  std::vector<char> connected(cell_count, 0), has_outlet(cell_count, 0);
  for (int c = 0; c < cell_count; ++c) {
    if (open_fraction[c] <= kClosedFraction) continue;
    for (int a = 0; a < 3; ++a)
      for (int sign : {-1, 1}) {
        int face = -1;
        const int other = across(a, sign, c, face);
        if (unknown[a][face] < 0) continue;
        if (other < 0) has_outlet[c] = 1;
        if (other != c) connected[c] = 1;
      }
  }
  active.assign(cell_count, -1);
  std::vector<int> region(cell_count, -1);
  for (int seed = 0; seed < cell_count; ++seed) {
    if (!connected[seed] || region[seed] >= 0) continue;
    std::vector<int> members;
    bool outlet = false;
    std::queue<int> queue;
    queue.push(seed);
    region[seed] = seed;
    while (!queue.empty()) {
      const int c = queue.front();
      queue.pop();
      members.push_back(c);
      outlet = outlet || has_outlet[c];
      for (int a = 0; a < 3; ++a)
        for (int sign : {-1, 1}) {
          int face = -1;
          const int other = across(a, sign, c, face);
          if (other >= 0 && unknown[a][face] >= 0 && region[other] < 0) {
            region[other] = seed;
            queue.push(other);
          }
        }
    }
    for (int c : members)
      if (outlet || c != seed) active[c] = 1;
  }
  active_cell.clear();
  for (int c = 0; c < cell_count; ++c)
    if (active[c] >= 0) {
      active[c] = static_cast<int>(active_cell.size());
      active_cell.push_back(c);
    }
  const int m = static_cast<int>(active_cell.size());
  std::vector<Triplet> entries;
  entries.reserve(7 * m);
  for (int u = 0; u < m; ++u) {
    entries.emplace_back(u, u, 0.0);
    for (int a = 0; a < 3; ++a)
      for (int sign : {-1, 1}) {
        int face = -1;
        const int other = across(a, sign, active_cell[u], face);
        if (other >= 0 && unknown[a][face] >= 0 && active[other] >= 0)
          entries.emplace_back(u, active[other], 0.0);
      }
  }
  pressure_pattern = pattern(m, entries);
  pressure_slot.assign(m, {-1, -1, -1, -1, -1, -1, -1});
  for (int u = 0; u < m; ++u) {
    pressure_slot[u][0] = entry_position(pressure_pattern, u, u);
    for (int a = 0; a < 3; ++a)
      for (int sign : {-1, 1}) {
        int face = -1;
        const int other = across(a, sign, active_cell[u], face);
        if (other >= 0 && unknown[a][face] >= 0 && active[other] >= 0)
          pressure_slot[u][1 + direction(a, sign)] = entry_position(pressure_pattern, u, active[other]);
      }
  }
}

int GasLayout::across(int axis, int sign, int cell, int& face) const {
  face = sign < 0 ? minus_face(axis, cell) : plus_face(axis, cell);
  return sign < 0 ? left[axis][face] : right[axis][face];
}

}  // namespace carom::gas_detail
