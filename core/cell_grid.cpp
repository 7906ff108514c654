#include "cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace carom {

namespace {
/// Expected prediction work per unit time for a given split of the sizes into levels, each
/// level's cells per diameter (reach) and cell widening (scale: cells of scale x diameter /
/// reach). Particles are taken as uniformly spread, at one temperature (speed ~ d^-3/2 at one
/// material density), colliding at the Enskog rate with the BMCSL contact values; each predicts
/// after each of its collisions (every cell that covers its cell) and after each of its cell
/// crossings (only the cells that came into reach). A prediction costs kEventCost, plus 1 per
/// cell visited, plus kCandidateCost per partner examined (a partner's record is a cache line,
/// a cell's first particle 4 bytes read in rows). The two weights were fitted to measured
/// times (tests/bench/README.md, "Polydisperse systems").
constexpr double kEventCost = 80.0;
constexpr double kCandidateCost = 3.0;

double prediction_cost(const Domain& domain, const std::vector<double>& sizes,
                       const std::vector<double>& counts, const std::vector<int>& level_of_size,
                       const std::vector<int>& reach, const std::vector<double>& scale) {
  const int levels = static_cast<int>(reach.size());
  const double volume = domain.volume();
  std::vector<double> cell(levels, 0.0), density(levels, 0.0), max_diameter(levels, 0.0);
  double total_cells = 0.0;
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const int l = level_of_size[s];
    max_diameter[l] = std::max(max_diameter[l], sizes[s]);
    density[l] += counts[s] / volume;
  }
  for (int l = 0; l < levels; ++l) {
    cell[l] = max_diameter[l] * scale[l] / reach[l];
    total_cells += volume / (cell[l] * cell[l] * cell[l]);
  }
  double particles = 0.0, phi = 0.0, xi2 = 0.0;
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    particles += counts[s];
    phi += counts[s] / volume * std::numbers::pi / 6.0 * sizes[s] * sizes[s] * sizes[s];
    xi2 += counts[s] / volume * std::numbers::pi / 6.0 * sizes[s] * sizes[s];
  }
  // Memory: 4 bytes a cell; allow up to 32 cells a particle plus 40 MB.
  if (total_cells > 32.0 * particles + 1e7) return std::numeric_limits<double>::infinity();
  const double free = 1.0 / std::max(1.0 - phi, 0.05);
  double cost = 0.0;
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const double d = sizes[s], mass = d * d * d;
    double collisions = 0.0;  // per unit time
    for (std::size_t t = 0; t < sizes.size(); ++t) {
      const double e = sizes[t], reduced = d * e / (d + e);
      const double contact = free + 3.0 * xi2 * reduced * free * free +
                             2.0 * xi2 * xi2 * reduced * reduced * free * free * free;
      collisions += counts[t] / volume * std::numbers::pi * 0.25 * (d + e) * (d + e) *
                    std::sqrt(8.0 / std::numbers::pi * (1.0 / mass + 1.0 / (e * e * e))) * contact;
    }
    const int own = level_of_size[s];
    const double crossings = 3.0 * std::sqrt(2.0 / std::numbers::pi / mass) / cell[own];
    double full = kEventCost, entering = kEventCost;
    for (int l = 0; l < levels; ++l) {
      double span, cells, band;
      if (l == own) {
        span = 2 * reach[l] + 1;
        cells = span * span * span;
        band = span * span;
      } else {
        span = (cell[own] + sizes[s] + max_diameter[l]) / cell[l] + 1.0;
        cells = span * span * span;
        band = span * span * std::min(span, cell[own] / cell[l]);
      }
      const double per_cell = 1.0 + kCandidateCost * cell[l] * cell[l] * cell[l] * density[l];
      full += cells * per_cell;
      entering += band * per_cell;
    }
    cost += counts[s] * (collisions * full + crossings * entering);
  }
  return cost;
}

/// A level's cells: cells per diameter (the block is (2 reach + 1)^3 cells) and widening.
struct CellChoice {
  int reach;
  double scale;
};
/// The choices the cost model weighs per level: 1-3 cells per diameter, or one cell of 1.5-4
/// diameters (fewer crossings and fewer cells to visit from other levels, more partners each).
/// The widened cells are offered to the finer levels only: the model's uniform, equal-
/// temperature gas misjudges a bed under gravity, and the largest level keeps the plain cells
/// that such beds have been measured with (tests/bench/README.md, "Polydisperse systems").
constexpr CellChoice kCellChoices[] = {{1, 1.0}, {2, 1.0}, {3, 1.0}, {1, 1.5},
                                       {1, 2.0}, {1, 3.0}, {1, 4.0}};
constexpr int kCellChoiceCount = sizeof(kCellChoices) / sizeof(kCellChoices[0]);
constexpr int kPlainCellChoiceCount = 3;  // the first three: cells of the diameter
/// The number of choices level l weighs.
int cell_choice_count(int l) {
  return l == 0 ? kPlainCellChoiceCount : kCellChoiceCount;
}
}  // namespace

HierarchicalGrid::LevelPlan HierarchicalGrid::cheapest_levels(const Domain& domain,
                                                               const std::vector<double>& sizes,
                                                               const std::vector<double>& counts,
                                                               int subdivision) {
  // Every split of the sorted sizes into consecutive groups (2^(k-1) of them, k <= 12), and
  // with subdivision 0 every cell choice of each level (up to 4 levels).
  const std::size_t k = sizes.size();
  double best_cost = std::numeric_limits<double>::infinity();
  LevelPlan best{{sizes.front()}, {std::max(subdivision, 1)}, {1.0}};
  for (std::uint32_t mask = 0; mask < (1u << (k - 1)); ++mask) {
    std::vector<int> level_of_size(k, 0);
    std::vector<double> nominal{sizes[0]};
    for (std::size_t s = 1; s < k; ++s) {
      const bool split = (mask >> (s - 1)) & 1u;
      if (split) nominal.push_back(sizes[s]);
      level_of_size[s] = static_cast<int>(nominal.size()) - 1;
    }
    const int levels = static_cast<int>(nominal.size());
    const bool search_cells = subdivision == 0 && levels <= 4;
    int combinations = 1;
    if (search_cells)
      for (int l = 0; l < levels; ++l) combinations *= cell_choice_count(l);
    for (int code = 0; code < combinations; ++code) {
      std::vector<int> reach(levels, std::max(subdivision, 1));
      std::vector<double> scale(levels, 1.0);
      if (search_cells)
        for (int l = 0, rest = code; l < levels; rest /= cell_choice_count(l), ++l) {
          reach[l] = kCellChoices[rest % cell_choice_count(l)].reach;
          scale[l] = kCellChoices[rest % cell_choice_count(l)].scale;
        }
      const double cost = prediction_cost(domain, sizes, counts, level_of_size, reach, scale);
      if (cost < best_cost * (1.0 - 1e-9)) {
        best_cost = cost;
        best = LevelPlan{nominal, reach, scale};
      }
    }
  }
  return best;
}

HierarchicalGrid::HierarchicalGrid(const Domain& domain, const std::vector<double>& radius,
                                   double level_ratio, int subdivision)
    : domain_(domain) {
  if (subdivision < 0 || subdivision > kMaxSubdivision)
    throw std::invalid_argument("grid subdivision must be between 0 (automatic) and " +
                                std::to_string(kMaxSubdivision));
  std::vector<double> diameters;
  for (double a : radius) diameters.push_back(2.0 * a);
  std::sort(diameters.begin(), diameters.end(), std::greater<>());
  std::vector<double> sizes;      // distinct diameters, largest first
  std::vector<double> counts;     // particles of each
  for (double d : diameters) {
    if (sizes.empty() || d != sizes.back()) {
      sizes.push_back(d);
      counts.push_back(0.0);
    }
    counts.back() += 1.0;
  }
  if (sizes.empty()) {
    sizes.push_back(domain.length().minCoeff() / 3.0);
    counts.push_back(0.0);
  }
  std::vector<int> level_reach;
  std::vector<double> level_scale;
  if (level_ratio < 0.0 && sizes.size() <= 12) {
    LevelPlan plan = cheapest_levels(domain, sizes, counts, subdivision);
    level_diameter_ = std::move(plan.diameters);
    level_reach = std::move(plan.reach);
    level_scale = std::move(plan.scale);
  } else {
    // Largest first; a size below level_ratio times the current level's starts a new level.
    for (double d : sizes)
      if (level_diameter_.empty() || d < level_ratio * level_diameter_.back()) level_diameter_.push_back(d);
    level_reach.assign(level_diameter_.size(), std::max(subdivision, 1));
    level_scale.assign(level_diameter_.size(), 1.0);
  }
  const Vec3 length = domain.length();
  for (std::size_t l = 0; l < level_diameter_.size(); ++l) {
    // Cells of at least the level's diameter: d is that diameter widened by the plan's scale.
    double d = level_diameter_[l] * level_scale[l];
    Level grid;
    // A periodic axis needs 2m + 2 cells: with fewer, the cells at the two ends are neighbours
    // both directly and through the boundary, and the nearest image at the time of a prediction
    // need not be the one that touches. A box too short for m cells per diameter gets fewer,
    // and widened cells fall back to the diameter first.
    int m = level_reach[l];
    auto fits = [&](int reach) {
      for (int k = 0; k < 3; ++k)
        if (domain.periodic[k] && std::floor(length[k] * reach / d) < 2 * reach + 2) return false;
      return true;
    };
    if (!fits(m)) d = level_diameter_[l];
    while (m > 1 && !fits(m)) --m;
    grid.reach = m;
    for (int k = 0; k < 3; ++k) {
      int n = static_cast<int>(std::floor(length[k] * m / d));
      n = std::clamp(n, 1, 1 << 20);
      if (domain.periodic[k] && n < 2 * m + 2)
        throw std::invalid_argument(
            "periodic axis " + std::string(1, "xyz"[k]) + " is " + std::to_string(length[k]) +
            " m long; it must be at least 4 particle diameters (" + std::to_string(4 * d) + " m)");
      grid.cells[k] = n;
      grid.cell_size[k] = length[k] / n;
    }
    const double total = double(grid.cells[0]) * grid.cells[1] * grid.cells[2];
    if (total > 2.0e8)
      throw std::invalid_argument("the cell grid for diameter " + std::to_string(d) + " m needs " +
                                  std::to_string(total) + " cells; the domain is too large");
    for (int k = 0; k < 3; ++k) grid.padded[k] = grid.cells[k] + 2 * m;
    grid.head.assign(std::size_t(grid.padded[0]) * grid.padded[1] * grid.padded[2], -1);
    grid.cell_bound.assign(grid.head.size(), 0.0);
    const auto offset = [&](int dx, int dy, int dz) {
      return dx + grid.padded[0] * (dy + grid.padded[1] * dz);
    };
    for (int dz = -m; dz <= m; ++dz)
      for (int dy = -m; dy <= m; ++dy)
        for (int dx = -m; dx <= m; ++dx) {
          grid.block_offsets.push_back(offset(dx, dy, dz));
          // The far face layers, in the block's order (z, then y, then x).
          const int d[3] = {dx, dy, dz};
          for (int k = 0; k < 3; ++k) {
            if (d[k] == -m) grid.slab_offsets[2 * k].push_back(offset(dx, dy, dz));
            if (d[k] == m) grid.slab_offsets[2 * k + 1].push_back(offset(dx, dy, dz));
          }
        }
    levels_.push_back(std::move(grid));
  }
  const std::size_t n = radius.size();
  next_.assign(n + 1, -1);
  prev_.assign(n, -1);
  place_.assign(n, Place{});
  for (std::size_t i = 0; i < n; ++i) {
    // The finest level whose nominal diameter still holds this particle.
    const double d = 2.0 * radius[i];
    int level = 0;
    for (int l = 0; l < static_cast<int>(level_diameter_.size()); ++l)
      if (level_diameter_[l] >= d) level = l;
    place_[i].level = static_cast<std::uint8_t>(level);
    levels_[level].max_radius = std::max(levels_[level].max_radius, radius[i]);
  }
}

std::array<int, 3> HierarchicalGrid::cell_coordinates(int level, const Vec3& r) const {
  const Level& grid = levels_[level];
  std::array<int, 3> c{};
  for (int k = 0; k < 3; ++k) {
    // Clamped before the conversion: a point far outside the box (a listed particle not yet
    // checked against the walls, found by fuzzing) or NaN must not overflow the int.
    const double x = std::floor((r[k] - domain_.lower[k]) / grid.cell_size[k]);
    c[k] = !(x >= 0.0) ? 0 : x >= grid.cells[k] - 1 ? grid.cells[k] - 1 : static_cast<int>(x);
  }
  return c;
}

template <class Visit>
void HierarchicalGrid::for_each_image(int level, const std::array<int, 3>& c, Visit&& visit) const {
  const Level& grid = levels_[level];
  const int m = grid.reach;
  // Per axis, the coordinates that stand for c[k]: itself, and on a periodic axis its image
  // in the halo beyond the opposite face (at most one: an axis has at least 2m + 2 cells).
  int images[3][2], count[3];
  for (int k = 0; k < 3; ++k) {
    const int n = grid.cells[k];
    images[k][0] = c[k];
    count[k] = 1;
    if (domain_.periodic[k] && c[k] < m) images[k][count[k]++] = c[k] + n;
    if (domain_.periodic[k] && c[k] >= n - m) images[k][count[k]++] = c[k] - n;
  }
  for (int a = 0; a < count[2]; ++a)
    for (int b = 0; b < count[1]; ++b)
      for (int d = 0; d < count[0]; ++d)
        visit(flat_index(level, {images[0][d], images[1][b], images[2][a]}));
}

void HierarchicalGrid::set_head(int level, const std::array<int, 3>& c, std::int32_t first) {
  std::int32_t* head = levels_[level].head.data();
  for_each_image(level, c, [&](std::int32_t flat) { head[flat] = first; });
}

void HierarchicalGrid::set_cell_bound(int level, const std::array<int, 3>& c, double value) {
  double* bound = levels_[level].cell_bound.data();
  for_each_image(level, c, [&](std::int32_t flat) { bound[flat] = value; });
}

void HierarchicalGrid::clear_cell_bounds() {
  for (Level& grid : levels_) std::fill(grid.cell_bound.begin(), grid.cell_bound.end(), 0.0);
}

double HierarchicalGrid::list_length_seen(int level) const {
  const Level& grid = levels_[level];
  double particles = 0.0, squares = 0.0;
  for (int z = 0; z < grid.cells[2]; ++z)
    for (int y = 0; y < grid.cells[1]; ++y)
      for (int x = 0; x < grid.cells[0]; ++x) {
        double count = 0.0;
        for (std::int32_t j = grid.head[flat_index(level, {x, y, z})]; j >= 0; j = next(j))
          count += 1.0;
        particles += count;
        squares += count * count;
      }
  return particles > 0.0 ? squares / particles : 0.0;
}

void HierarchicalGrid::link(std::int32_t i) {
  const std::int32_t head =
      levels_[place_[i].level].head[flat_index(place_[i].level, place_[i].cell)];
  prev_[i] = -1;
  next_[i + 1] = head;
  if (head >= 0) prev_[head] = i;
  set_head(place_[i].level, place_[i].cell, i);
}

void HierarchicalGrid::unlink(std::int32_t i) {
  const std::int32_t after = next_[i + 1];
  if (prev_[i] >= 0)
    next_[prev_[i] + 1] = after;
  else
    set_head(place_[i].level, place_[i].cell, after);
  if (after >= 0) prev_[after] = prev_[i];
  next_[i + 1] = prev_[i] = -1;
}

void HierarchicalGrid::insert(std::int32_t i, const Vec3& r) {
  place_[i].cell = cell_coordinates(place_[i].level, r);
  link(i);
}

Vec3 HierarchicalGrid::cross(std::int32_t i, int axis, int direction) {
  unlink(i);
  const Level& grid = levels_[place_[i].level];
  Vec3 shift = Vec3::Zero();
  int idx = place_[i].cell[axis] + direction;
  if (idx < 0) {
    idx += grid.cells[axis];
    shift[axis] = domain_.length()[axis];
  } else if (idx >= grid.cells[axis]) {
    idx -= grid.cells[axis];
    shift[axis] = -domain_.length()[axis];
  }
  place_[i].cell[axis] = idx;
  link(i);
  return shift;
}

bool HierarchicalGrid::block_wraps(int level, const std::array<int, 3>& c, const int (&from)[3],
                                   const int (&to)[3]) const {
  const auto& n = levels_[level].cells;
  for (int k = 0; k < 3; ++k)
    if (domain_.periodic[k] && (c[k] + from[k] < 0 || c[k] + to[k] >= n[k])) return true;
  return false;
}

int HierarchicalGrid::cells_around(std::int32_t i, const std::vector<std::int32_t>& offsets,
                                   const int (&from)[3], const int (&to)[3], std::int32_t* cells,
                                   bool& wrapped) const {
  const Place& at = place_[i];
  wrapped = block_wraps(at.level, at.cell, from, to);
  const std::int32_t centre = flat_index(at.level, at.cell);
  const int count = static_cast<int>(offsets.size());
  for (int k = 0; k < count; ++k) cells[k] = centre + offsets[k];
  return count;
}

int HierarchicalGrid::own_block(std::int32_t i, std::int32_t* cells, bool& wrapped) const {
  const Level& grid = levels_[place_[i].level];
  const int m = grid.reach;
  const int from[3] = {-m, -m, -m}, to[3] = {m, m, m};
  return cells_around(i, grid.block_offsets, from, to, cells, wrapped);
}

int HierarchicalGrid::own_slab(std::int32_t i, int axis, int direction, std::int32_t* cells,
                               bool& wrapped) const {
  const Level& grid = levels_[place_[i].level];
  const int m = grid.reach;
  int from[3] = {-m, -m, -m}, to[3] = {m, m, m};
  from[axis] = to[axis] = direction * m;
  return cells_around(i, grid.slab_offsets[2 * axis + (direction > 0 ? 1 : 0)], from, to, cells,
                      wrapped);
}

HierarchicalGrid::AxisRange HierarchicalGrid::clip(int level, int k, int first, int last) const {
  AxisRange range;
  const int n = levels_[level].cells[k];
  range.cells = n;
  if (domain_.periodic[k]) {
    range.wrap = true;
    range.count = std::min(last - first + 1, n);
    if (range.count == n) first = 0;
    // Bring the start into [0, n) so that one subtraction of n wraps every index.
    range.first = ((first % n) + n) % n;
  } else {
    first = std::max(first, 0);
    last = std::min(last, n - 1);
    range.first = first;
    range.count = std::max(0, last - first + 1);
  }
  return range;
}

HierarchicalGrid::RawRanges HierarchicalGrid::covering_raw(std::int32_t i, int level,
                                                           const std::array<int, 3>& cell) const {
  // The bounds of `cell` as cell_lower and cell_upper compute them for i's own cell, grown as
  // for_each_candidate grows them.
  const Level& own = levels_[place_[i].level];
  const Level& grid = levels_[level];
  const double reach = reach_between(place_[i].level, level);
  RawRanges raw;
  for (int k = 0; k < 3; ++k) {
    const double lower = domain_.lower[k] + cell[k] * own.cell_size[k];
    const double upper = cell[k] + 1 == own.cells[k]
                             ? domain_.upper[k]
                             : domain_.lower[k] + (cell[k] + 1) * own.cell_size[k];
    raw.first[k] =
        static_cast<int>(std::floor((lower - reach - domain_.lower[k]) / grid.cell_size[k]));
    raw.last[k] =
        static_cast<int>(std::floor((upper + reach - domain_.lower[k]) / grid.cell_size[k]));
  }
  return raw;
}

HierarchicalGrid::AxisRange HierarchicalGrid::covering(int level, int k, double lo, double hi) const {
  const Level& grid = levels_[level];
  const int first = static_cast<int>(std::floor((lo - domain_.lower[k]) / grid.cell_size[k]));
  const int last = static_cast<int>(std::floor((hi - domain_.lower[k]) / grid.cell_size[k]));
  return clip(level, k, first, last);
}

}  // namespace carom
