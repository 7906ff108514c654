#pragma once
/// A hierarchical cell grid: the neighbour structure that stays fast for polydisperse systems.
///
/// Particles are sorted by size into levels; each level is a uniform grid whose cells are at least
/// as wide as the largest diameter in the level. A particle lives in one cell of its own level and
/// its predictions are valid until it leaves that cell (a cell-crossing event). To find every
/// partner it could touch before then, it visits, on each level, the cells that overlap its own
/// cell grown by (its radius + the largest radius of that level). On its own level that is the
/// 3x3x3 block around it; fines looking up at large particles visit a handful of coarse cells;
/// large particles looking down visit the fine cells around them. With one grid sized by the
/// largest particle, fines 10x smaller would put ~1000 of them in every cell.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "domain.hpp"
#include "huge_pages.hpp"
#include "vec3.hpp"

namespace carom {

class HierarchicalGrid {
 public:
  /// One uniform grid.
  struct Level {
    std::array<int, 3> cells{1, 1, 1};  ///< Number of cells per axis.
    Vec3 cell_size = Vec3::Ones();      ///< Cell edge per axis, m (>= the largest diameter).
    double max_radius = 0;              ///< Largest particle radius in this level, m.
    int reach = 1;                      ///< Cells per diameter m: the block is (2m+1)^3 cells.
    /// Cells per axis with a halo of m cells on each side. A halo cell of a periodic axis holds
    /// a copy of the first particle of the cell it is an image of; on a walled axis it stays
    /// empty. Every block is then a fixed set of flat offsets, at the box's faces too.
    std::array<int, 3> padded{1, 1, 1};
    BigVector<std::int32_t> head;  ///< First particle of each (padded) cell's list, or -1.
    /// Per (padded) cell, an upper bound that the caller keeps on a quantity of the cell's
    /// particles (raise_cell_bound); a halo cell of a periodic axis holds its image's.
    BigVector<double> cell_bound;
    std::vector<std::int32_t> block_offsets;  ///< Flat offsets of the block around a cell.
    /// Flat offsets of the far face layer of the block, per face (2 axis + (direction > 0)).
    std::array<std::vector<std::int32_t>, 6> slab_offsets;
  };

  HierarchicalGrid() = default;
  /// Builds the levels for particles of the given radii. level_ratio < 0 (the default) picks
  /// the split of sizes into levels with the least expected prediction work (cells visited plus
  /// partners examined, from the sizes, counts and box volume); level_ratio > 0 starts a new
  /// level whenever a diameter is below level_ratio times the current level's; level_ratio = 0
  /// puts every particle in one grid. Throws std::invalid_argument when a periodic axis is
  /// shorter than three cells.
  /// `subdivision` m cuts each level's cells to 1/m of its largest diameter; the own-level
  /// search block is then (2m+1)^3 cells. subdivision = 0 lets the cost model choose the cells
  /// of each level: m per diameter (large particles among fines search fewer fine cells with
  /// smaller own cells), or one cell of up to 4 diameters (fast fines cross fewer cells, and
  /// large particles visit fewer of them).
  HierarchicalGrid(const Domain& domain, const std::vector<double>& radius, double level_ratio = -1.0,
                   int subdivision = 1);
  /// Levels as planned: nominal (largest) diameter, cells per diameter and the widening of the
  /// cells (cells of scale x diameter / reach) of each.
  struct LevelPlan {
    std::vector<double> diameters;
    std::vector<int> reach;
    std::vector<double> scale;
  };
  /// The cheapest levels for distinct `sizes` (largest first) with `counts` particles each
  /// (see the constructor).
  static LevelPlan cheapest_levels(const Domain& domain, const std::vector<double>& sizes,
                                   const std::vector<double>& counts, int subdivision);
  /// Largest supported subdivision.
  static constexpr int kMaxSubdivision = 3;
  /// Largest number of cells in an own-level block.
  static constexpr int kMaxBlock = (2 * kMaxSubdivision + 1) * (2 * kMaxSubdivision + 1) * (2 * kMaxSubdivision + 1);

  /// Places particle i (centre r) in its cell, on its level.
  void insert(std::int32_t i, const Vec3& r);
  /// Places particle i in the given cell of its level (restoring a saved state).
  void insert_at(std::int32_t i, const std::array<int, 3>& cell) {
    place_[i].cell = cell;
    link(i);
  }
  /// Takes particle i out of the grid (it can be inserted again).
  void remove(std::int32_t i) { unlink(i); }
  /// Moves particle i to the neighbouring cell across face (axis, +1 or -1), wrapping periodic axes.
  /// Returns the shift to add to the particle's stored position (non-zero after a periodic wrap).
  Vec3 cross(std::int32_t i, int axis, int direction);

  /// Level of particle i.
  int level_of(std::int32_t i) const { return place_[i].level; }
  /// Cell coordinates of particle i on its level.
  const std::array<int, 3>& cell_of(std::int32_t i) const { return place_[i].cell; }
  /// Asks the CPU to start loading particle i's place (a hint; changes nothing). Always
  /// inlined: GCC deletes calls to a function of prefetches alone.
  [[gnu::always_inline]] void prefetch(std::int32_t i) const { __builtin_prefetch(&place_[i]); }
  /// Asks the CPU to start loading the first particles of the cells of i's own-level block
  /// (what the own-level scan reads first; a hint, changes nothing).
  [[gnu::always_inline]] void prefetch_own_block(std::int32_t i) const {
    const Place& at = place_[i];
    const Level& grid = levels_[at.level];
    const std::int32_t* centre = grid.head.data() + flat_index(at.level, at.cell);
    for (const std::int32_t offset : grid.block_offsets) __builtin_prefetch(centre + offset);
  }
  /// Flat index (as own_block's) of the cell across `face` (2 axis + (direction > 0)) of
  /// particle i's cell, wrapped on a periodic axis: i's cell once it has crossed that face (not
  /// an outer face). own_slab's cells after the crossing are this plus the level's
  /// slab_offsets[face].
  std::int32_t cell_across(std::int32_t i, int face) const {
    const Place& at = place_[i];
    std::array<int, 3> c = at.cell;
    const int axis = face / 2, n = levels_[at.level].cells[axis];
    c[axis] += (face % 2) ? 1 : -1;
    if (c[axis] == n) c[axis] = 0;
    if (c[axis] < 0) c[axis] = n - 1;
    return flat_index(at.level, c);
  }
  /// Asks the CPU to start loading the first particles of the cells that come into reach when
  /// particle i crosses `face` (what the crossing's own-level scan reads first; a hint, changes
  /// nothing). Always inlined: GCC deletes calls to a function of prefetches alone.
  [[gnu::always_inline]] void prefetch_entering_slab(std::int32_t i, int face) const {
    const Level& grid = levels_[place_[i].level];
    const std::int32_t* centre = grid.head.data() + cell_across(i, face);
    for (const std::int32_t offset : grid.slab_offsets[face]) __builtin_prefetch(centre + offset);
  }
  /// How many particles come before i in its cell's list (0: the first). Scans visit a cell's
  /// particles in this order, and a relax prediction's round-off depends on it, so a restored
  /// grid must keep it (insert_at the particles in order of decreasing place).
  int place_in_cell(std::int32_t i) const {
    int place = 0;
    for (std::int32_t j = prev_[i]; j >= 0; j = prev_[j]) ++place;
    return place;
  }
  /// Raises the bound of particle i's cell (and of its periodic images) to `value` if it is
  /// below: a caller that raises it for every particle whose quantity may have grown keeps each
  /// cell's bound at or above the largest value among the particles there since the last
  /// clear_cell_bounds (a particle that leaves a cell leaves its value behind).
  void raise_cell_bound(std::int32_t i, double value) {
    const Place& at = place_[i];
    if (value > levels_[at.level].cell_bound[flat_index(at.level, at.cell)])
      set_cell_bound(at.level, at.cell, value);
  }
  /// Sets every cell's bound to 0.
  void clear_cell_bounds();
  /// The bound of each cell of `level`, indexed as head_array.
  const double* cell_bound_array(int level) const { return levels_[level].cell_bound.data(); }
  /// Lower corner of particle i's cell, m.
  Vec3 cell_lower(std::int32_t i) const {
    const Level& grid = levels_[place_[i].level];
    const auto& c = place_[i].cell;
    return {domain_.lower.x() + c[0] * grid.cell_size.x(), domain_.lower.y() + c[1] * grid.cell_size.y(),
            domain_.lower.z() + c[2] * grid.cell_size.z()};
  }
  /// Upper corner of particle i's cell, m (the box's upper face exactly for the last cell).
  Vec3 cell_upper(std::int32_t i) const {
    const Level& grid = levels_[place_[i].level];
    const auto& c = place_[i].cell;
    Vec3 upper;
    for (int k = 0; k < 3; ++k)
      upper[k] = c[k] + 1 == grid.cells[k] ? domain_.upper[k]
                                           : domain_.lower[k] + (c[k] + 1) * grid.cell_size[k];
    return upper;
  }
  /// True when the face (axis, direction) of particle i's cell is on the boundary of a walled
  /// (non-periodic) axis, so that no crossing through it is ever expected.
  bool is_outer_face(std::int32_t i, int axis, int direction) const {
    if (domain_.periodic[axis]) return false;
    const int idx = place_[i].cell[axis];
    return direction < 0 ? idx == 0 : idx + 1 == levels_[place_[i].level].cells[axis];
  }

  const std::vector<Level>& levels() const { return levels_; }
  const Domain& domain() const { return domain_; }

  /// Calls visit(j) for every particle j != i that could touch i while i stays in its cell.
  /// On another level these are the particles of the cells that overlap i's cell grown by the
  /// reach between the two levels (reach_between): the same for every particle of a level, so
  /// that j's cell is among i's exactly when i's is among j's. A crossing searches only the
  /// cells that came into reach, and a pair whose cells came within reach when one of them
  /// crossed is found by that one only because of this symmetry: grown by i's own radius
  /// instead, a small particle of a level missed partners whose cells a larger one of its
  /// level would have reached (tests/test_grid_levels_run.cpp).
  template <class Visit>
  void for_each_candidate(std::int32_t i, Visit&& visit) const {
    for_each_candidate_on_levels(i, /*include_own=*/true, visit);
  }
  /// As for_each_candidate, but only on the levels other than i's own.
  template <class Visit>
  void for_each_candidate_on_other_levels(std::int32_t i, Visit&& visit) const {
    for_each_candidate_on_levels(i, /*include_own=*/false, visit);
  }
  /// The reach between two levels, m: the largest contact distance of a particle of one with a
  /// particle of the other (the sum of their largest radii).
  double reach_between(int level, int other) const {
    return levels_[level].max_radius + levels_[other].max_radius;
  }
  /// The fast path for i's own level: writes the flat (padded) indices of the (2m+1)^3 cells of
  /// the block around i's cell into `cells` and returns how many (beyond a walled face they are
  /// empty halo cells). `wrapped` tells whether the block crosses a periodic boundary (then
  /// partners need the minimum image).
  int own_block(std::int32_t i, std::int32_t* cells, bool& wrapped) const;
  /// The cells that entered i's own-level block when it just crossed into its cell along
  /// (axis, direction): the far face layer of the block. Same conventions as own_block.
  int own_slab(std::int32_t i, int axis, int direction, std::int32_t* cells, bool& wrapped) const;
  /// The cells of another `level` that hold every particle i could touch while it stays in its
  /// cell (those for_each_candidate visits there), in the order for_each_candidate visits them: handed to
  /// visit(cells, count, wrapped) as flat (padded) indices of `level`, at most kMaxBlock at a
  /// time. `wrapped` tells whether they cross a periodic face (partners then need the minimum
  /// image).
  template <class Visit>
  void for_each_covering_piece(std::int32_t i, int level, Visit&& visit) const {
    RawRanges raw = covering_raw(i, level, place_[i].cell);
    visit_ranges(level, raw, visit);
  }
  /// The cells of for_each_covering_piece whose box lies within within() (m) of the point p:
  /// i's position at some time when every particle of `level` lies in its cell (the boxes are
  /// taken in i's frame, the image around i's cell; the edge cells of a walled axis reach to
  /// infinity, as they hold the particles beyond the box). First those within first_reach (m),
  /// then the others, each pass z outermost and x innermost, in pieces of at most kNearPiece;
  /// within() is asked at the start of the second pass and after each of its pieces, so a
  /// caller whose bound shrinks as it finds partners skips more. Where a range along an axis
  /// is longer than kNearAxis cells, every covering cell, as for_each_covering_piece.
  template <class Within, class Visit>
  void for_each_covering_piece_near(std::int32_t i, int level, const Vec3& p, double first_reach,
                                    Within&& within, Visit&& visit) const;
  /// Most cells of a piece of for_each_covering_piece_near: the bound is asked again after each.
  static constexpr int kNearPiece = 64;
  /// Longest range of cells per axis that for_each_covering_piece_near bounds.
  static constexpr int kNearAxis = 32;
  /// As for_each_covering_piece, but only the cells that came into reach when i just crossed
  /// into its cell along (axis, direction): those not covered from the cell it came from. After
  /// a crossing through a periodic face (its position was shifted by a box length), or where
  /// the reach spans a whole periodic axis, every covering cell.
  template <class Visit>
  void for_each_entering_piece(std::int32_t i, int level, int axis, int direction,
                               Visit&& visit) const {
    const std::array<int, 3>& cell = place_[i].cell;
    RawRanges raw = covering_raw(i, level, cell);
    std::array<int, 3> before = cell;
    before[axis] -= direction;
    const int n = levels_[level].cells[axis];
    const bool full_lap = domain_.periodic[axis] && raw.last[axis] - raw.first[axis] + 1 >= n;
    if (before[axis] >= 0 && before[axis] < levels_[place_[i].level].cells[axis] && !full_lap) {
      const RawRanges old = covering_raw(i, level, before);
      if (direction > 0)
        raw.first[axis] = std::max(raw.first[axis], old.last[axis] + 1);
      else
        raw.last[axis] = std::min(raw.last[axis], old.first[axis] - 1);
      if (raw.last[axis] < raw.first[axis]) return;
    }
    visit_ranges(level, raw, visit);
  }
  /// First particle in flat (padded) cell `cell` of `level`, or -1.
  std::int32_t head(int level, std::int32_t cell) const { return levels_[level].head[cell]; }
  /// The first particle of each cell of `level` (index by flat padded cell, as own_block
  /// writes them), -1 for an empty cell.
  const std::int32_t* head_array(int level) const { return levels_[level].head.data(); }
  /// The particle after j in its cell's list, or -1.
  std::int32_t next(std::int32_t j) const { return next_[j + 1]; }
  /// How many particles the cell of a particle of `level` holds, averaged over those particles
  /// (the sum of the cells' counts squared over the sum of the counts; 0 on an empty level):
  /// how long the lists are that a prediction on that level walks.
  double list_length_seen(int level) const;
  /// The neighbour lists: next[j] is next(j), for every particle j and for j = -1 (the end of
  /// a list is its own successor, -1), so a walk can go past a list's end without a branch.
  const std::int32_t* next_array() const { return next_.data() + 1; }

  /// Cell coordinates on `level` of a point (clamped into the grid).
  std::array<int, 3> cell_coordinates(int level, const Vec3& r) const;

 private:
  /// Flat index in the padded grid of `level` of the cell with coordinates c (each in
  /// [-m, n + m) on its axis).
  std::int32_t flat_index(int level, const std::array<int, 3>& c) const {
    const Level& grid = levels_[level];
    const int m = grid.reach;
    return (c[0] + m) + grid.padded[0] * ((c[1] + m) + grid.padded[1] * (c[2] + m));
  }
  /// Sets the first particle of cell c of `level`, and of its periodic images in the halo.
  void set_head(int level, const std::array<int, 3>& c, std::int32_t first);
  /// Sets the bound of cell c of `level`, and of its periodic images in the halo.
  void set_cell_bound(int level, const std::array<int, 3>& c, double value);
  /// Calls visit(flat index) for cell c of `level` and each of its periodic images in the halo.
  template <class Visit>
  void for_each_image(int level, const std::array<int, 3>& c, Visit&& visit) const;
  /// True when the block of `level` from c + from to c + to (per axis) crosses a periodic face.
  bool block_wraps(int level, const std::array<int, 3>& c, const int (&from)[3],
                   const int (&to)[3]) const;
  /// The cells at `offsets` from particle i's cell on its level, into `cells` (returns how
  /// many); `wrapped` as block_wraps over the per-axis span [from, to] those offsets cover.
  int cells_around(std::int32_t i, const std::vector<std::int32_t>& offsets, const int (&from)[3],
                   const int (&to)[3], std::int32_t* cells, bool& wrapped) const;
  void link(std::int32_t i);
  void unlink(std::int32_t i);
  template <class Visit>
  void for_each_candidate_on_levels(std::int32_t i, bool include_own, Visit&& visit) const;
  /// A run of consecutive cell indices along one axis, wrapped on periodic axes.
  struct AxisRange {
    int first = 0;   ///< First index (may be negative or past the end before wrapping).
    int count = 0;   ///< Number of cells.
    int cells = 1;   ///< Cells on this axis.
    bool wrap = false;
    int at(int m) const {
      const int idx = first + m;
      return wrap ? (idx < 0 ? idx + cells : (idx >= cells ? idx - cells : idx)) : idx;
    }
  };
  /// Cells of a level as unclipped index intervals per axis (may reach past the box).
  struct RawRanges {
    int first[3], last[3];
  };
  /// The cells of `level` that overlap the cell `cell` of i's level grown by the reach between
  /// the two levels, unclipped.
  RawRanges covering_raw(std::int32_t i, int level, const std::array<int, 3>& cell) const;
  /// Hands the cells of `raw` (clipped, periodic axes wrapped) to visit(cells, count, wrapped)
  /// in pieces of at most kMaxBlock, z outermost and x innermost.
  template <class Visit>
  void visit_ranges(int level, const RawRanges& raw, Visit&& visit) const;
  /// Cells [first, last] on `level`, axis k: clamped on walled axes, at most one lap on periodic.
  AxisRange clip(int level, int k, int first, int last) const;
  /// The cells on `level`, axis k, that overlap the interval [lo, hi] (m).
  AxisRange covering(int level, int k, double lo, double hi) const;

  Domain domain_;
  std::vector<Level> levels_;
  std::vector<double> level_diameter_;  ///< Nominal (largest) diameter of each level, m.
  /// The particle after j in its cell's list is next_[j + 1] (-1 at the end); next_[0] = -1
  /// stands for the end's own successor, so that a walk may read one past the end without a
  /// branch (next_array).
  BigVector<std::int32_t> next_;
  BigVector<std::int32_t> prev_;
  /// Where a particle is: its level and its cell there. Read together at every prediction,
  /// so kept together (one cache miss, not two).
  struct Place {
    std::array<int, 3> cell{0, 0, 0};  ///< Cell coordinates on the level.
    std::uint8_t level = 0;
  };
  BigVector<Place> place_;  ///< Per particle.
};

template <class Visit>
void HierarchicalGrid::for_each_candidate_on_levels(std::int32_t i, bool include_own,
                                                    Visit&& visit) const {
  const int own = place_[i].level;
  for (int level = 0; level < static_cast<int>(levels_.size()); ++level) {
    if (level == own && !include_own) continue;
    const Level& grid = levels_[level];
    AxisRange range[3];
    if (level == own) {
      // The 3x3x3 block: the cell is wider than any contact distance within the level.
      for (int k = 0; k < 3; ++k)
        range[k] = clip(level, k, place_[i].cell[k] - grid.reach, place_[i].cell[k] + grid.reach);
    } else {
      const Vec3 lower = cell_lower(i), upper = cell_upper(i);
      const double reach = reach_between(own, level);
      for (int k = 0; k < 3; ++k) range[k] = covering(level, k, lower[k] - reach, upper[k] + reach);
    }
    for (int a = 0; a < range[2].count; ++a) {
      const int z = range[2].at(a);
      for (int b = 0; b < range[1].count; ++b) {
        const int y = range[1].at(b);
        for (int d = 0; d < range[0].count; ++d) {
          for (std::int32_t j = grid.head[flat_index(level, {range[0].at(d), y, z})]; j >= 0;
               j = next(j))
            if (j != i) visit(j);
        }
      }
    }
  }
}

template <class Within, class Visit>
void HierarchicalGrid::for_each_covering_piece_near(std::int32_t i, int level, const Vec3& p,
                                                    double first_reach, Within&& within,
                                                    Visit&& visit) const {
  const RawRanges raw = covering_raw(i, level, place_[i].cell);
  const Level& grid = levels_[level];
  AxisRange range[3];
  bool wrapped = false;
  // Per axis and place in its range, the squared distance from p to the cells' slab.
  double gap2[3][kNearAxis];
  for (int k = 0; k < 3; ++k) {
    range[k] = clip(level, k, raw.first[k], raw.last[k]);
    if (range[k].count == 0) return;
    if (range[k].count > kNearAxis) {
      visit_ranges(level, raw, visit);
      return;
    }
    wrapped |= domain_.periodic[k] && (raw.first[k] < 0 || raw.last[k] >= range[k].cells);
    const bool lap = domain_.periodic[k] && range[k].count == range[k].cells;
    // The first cell's index in i's frame: the raw one on a periodic axis (its image next to
    // i's cell), the clipped one on a walled axis.
    const int first = domain_.periodic[k] ? raw.first[k] : range[k].first;
    const double h = grid.cell_size[k], inf = std::numeric_limits<double>::infinity();
    for (int a = 0; a < range[k].count; ++a) {
      const int m = first + a;
      double lower = domain_.lower[k] + m * h, upper = lower + h;
      if (!domain_.periodic[k] && m == 0) lower = -inf;
      if (!domain_.periodic[k] && m == range[k].cells - 1) upper = inf;
      const double gap = lap ? 0.0 : std::max({0.0, lower - p[k], p[k] - upper});
      gap2[k][a] = gap * gap;
    }
  }
  std::int32_t cells[kNearPiece];
  int count = 0;
  // Two passes: the cells within `first_reach` of p, then the others within reach (asked
  // again after each piece). The first ones hold the likely earliest partners, so that the
  // second pass starts with a near bound.
  double reach = std::min(first_reach, within()), reach2 = reach * reach, inner2 = -1.0;
  auto take = [&](int from, int to, int y, int z, bool ask) {
    for (int d = from; d <= to; ++d) {
      cells[count++] = flat_index(level, {range[0].at(d), y, z});
      if (count == kNearPiece) {
        visit(cells, count, wrapped);
        count = 0;
        if (ask) {
          reach = within();
          reach2 = reach * reach;
        }
      }
    }
  };
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      inner2 = reach2;
      reach = within();
      reach2 = reach * reach;
    }
    for (int a = 0; a < range[2].count; ++a) {
      if (gap2[2][a] > reach2) continue;
      const int z = range[2].at(a);
      for (int b = 0; b < range[1].count; ++b) {
        const double zy = gap2[2][a] + gap2[1][b];
        if (zy > reach2) continue;
        const int y = range[1].at(b);
        // A row's cells within a distance are one run (the gaps fall to 0 at p and rise).
        int first = 0, last = range[0].count - 1;
        while (first <= last && zy + gap2[0][first] > reach2) ++first;
        while (last >= first && zy + gap2[0][last] > reach2) --last;
        if (zy > inner2) {
          take(first, last, y, z, pass == 1);
          continue;
        }
        int skip_first = first, skip_last = last;  // the first pass's run
        while (skip_first <= skip_last && zy + gap2[0][skip_first] > inner2) ++skip_first;
        while (skip_last >= skip_first && zy + gap2[0][skip_last] > inner2) --skip_last;
        take(first, skip_first - 1, y, z, true);
        take(skip_last + 1, last, y, z, true);
      }
    }
  }
  if (count > 0) visit(cells, count, wrapped);
}

template <class Visit>
void HierarchicalGrid::visit_ranges(int level, const RawRanges& raw, Visit&& visit) const {
  AxisRange range[3];
  bool wrapped = false;
  for (int k = 0; k < 3; ++k) {
    range[k] = clip(level, k, raw.first[k], raw.last[k]);
    if (range[k].count == 0) return;
    wrapped |= domain_.periodic[k] && (raw.first[k] < 0 || raw.last[k] >= range[k].cells);
  }
  std::int32_t cells[kMaxBlock];
  int count = 0;
  for (int a = 0; a < range[2].count; ++a) {
    const int z = range[2].at(a);
    for (int b = 0; b < range[1].count; ++b) {
      const int y = range[1].at(b);
      for (int d = 0; d < range[0].count; ++d) {
        if (count == kMaxBlock) {
          visit(cells, count, wrapped);
          count = 0;
        }
        cells[count++] = flat_index(level, {range[0].at(d), y, z});
      }
    }
  }
  if (count > 0) visit(cells, count, wrapped);
}

}  // namespace carom
