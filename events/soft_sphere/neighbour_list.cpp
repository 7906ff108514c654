#include "events/soft_sphere/neighbour_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace carom {

namespace {

/// The uniform grid of one build: cells at least `cell` wide, particles sorted by cell.
struct CellSort {
  std::array<int, 3> cells{1, 1, 1};
  Vec3 size = Vec3::Ones();
  std::vector<std::int32_t> start;   // first sorted index of each cell; size cells + 1
  std::vector<std::int32_t> sorted;  // particle indices by cell

  std::array<int, 3> cell_of(const Domain& d, const Vec3& r) const {
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k) {
      // Clamped before the conversion: a position far outside the box (a run blowing up, which
      // the run's speed bound then stops) must not overflow the int; NaN goes to cell 0.
      const double x = std::floor((r[k] - d.lower[k]) / size[k]);
      c[k] = x > 0.0 ? static_cast<int>(std::min(x, static_cast<double>(cells[k] - 1))) : 0;
    }
    return c;
  }
  int flat(const std::array<int, 3>& c) const { return (c[2] * cells[1] + c[1]) * cells[0] + c[0]; }
};

CellSort sort_into_cells(const Domain& d, double cell, const std::vector<Vec3>& position) {
  CellSort g;
  const Vec3 length = d.length();
  // At most about 4 cells per particle (a dilute gas would otherwise allocate empty cells).
  const double budget = 4.0 * static_cast<double>(std::max<std::size_t>(position.size(), 8));
  for (;;) {
    double total = 1.0;
    for (int k = 0; k < 3; ++k) {
      g.cells[k] = std::max(1, static_cast<int>(std::floor(length[k] / cell)));
      total *= g.cells[k];
    }
    if (total <= budget) break;
    cell *= 1.25;
  }
  for (int k = 0; k < 3; ++k) g.size[k] = length[k] / g.cells[k];
  const std::size_t n_cells = static_cast<std::size_t>(g.cells[0]) * g.cells[1] * g.cells[2];
  std::vector<std::int32_t> home(position.size());
  g.start.assign(n_cells + 1, 0);
  for (std::size_t i = 0; i < position.size(); ++i) {
    home[i] = g.flat(g.cell_of(d, position[i]));
    ++g.start[home[i] + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c) g.start[c + 1] += g.start[c];
  g.sorted.resize(position.size());
  std::vector<std::int32_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < position.size(); ++i) g.sorted[fill[home[i]]++] = static_cast<std::int32_t>(i);
  return g;
}

/// The cell indices along one axis within `reach` cells of `centre`, each once, as runs of
/// consecutive cells [first, last] (a periodic axis wraps: two runs).
void axis_runs(int centre, int reach, int cells, bool periodic,
               std::vector<std::array<int, 2>>& out) {
  out.clear();
  if (periodic && 2 * reach + 1 >= cells) {
    out.push_back({0, cells - 1});
    return;
  }
  int lo = centre - reach, hi = centre + reach;
  if (!periodic) {
    out.push_back({std::max(lo, 0), std::min(hi, cells - 1)});
  } else if (lo < 0) {
    out.push_back({lo + cells, cells - 1});
    out.push_back({0, hi});
  } else if (hi >= cells) {
    out.push_back({lo, cells - 1});
    out.push_back({0, hi - cells});
  } else {
    out.push_back({lo, hi});
  }
}

}  // namespace

void NeighbourList::build(const std::vector<Vec3>& position, const std::vector<double>& radius,
                          const std::vector<Wall>& walls) {
  const std::size_t n = position.size();
  double smallest = n > 0 ? radius[0] : 1.0;
  for (double a : radius) smallest = std::min(smallest, a);
  const CellSort grid = sort_into_cells(domain_, 2.0 * smallest + skin_, position);
  std::vector<CellEntry>& entries = entries_;
  entries.resize(n);
  for (std::size_t s = 0; s < n; ++s) {
    const std::int32_t j = grid.sorted[s];
    entries[s] = CellEntry{position[j], radius[j], j};
  }

  std::vector<PairContactState> fresh = std::move(spare_pairs_);
  fresh.clear();
  fresh.reserve(pairs_.size() + n);
  std::vector<std::int32_t> found;
  std::array<std::vector<std::array<int, 2>>, 3> runs;
  for (std::size_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::int32_t>(ii);
    const double a_i = radius[ii];
    const Vec3 r_i = position[ii];
    const auto home = grid.cell_of(domain_, r_i);
    for (int k = 0; k < 3; ++k) {
      const int reach = static_cast<int>(std::ceil((2.0 * a_i + skin_) / grid.size[k]));
      axis_runs(home[k], reach, grid.cells[k], domain_.periodic[k], runs[k]);
    }
    found.clear();
    for (const auto& [z0, z1] : runs[2])
      for (int cz = z0; cz <= z1; ++cz)
        for (const auto& [y0, y1] : runs[1])
          for (int cy = y0; cy <= y1; ++cy)
            for (const auto& [x0, x1] : runs[0]) {
              // Cells x0 ... x1 of this row: one stretch of the entries.
              const std::int32_t end = grid.start[grid.flat({x1, cy, cz}) + 1];
              for (std::int32_t s = grid.start[grid.flat({x0, cy, cz})]; s < end; ++s) {
                const CellEntry& e = entries[s];
                if (!owns(a_i, i, e.radius, e.index)) continue;
                Vec3 d = r_i - e.position;
                domain_.minimum_image(d);
                const double reach = a_i + e.radius + skin_;
                if (d.squaredNorm() < reach * reach) found.push_back(e.index);
              }
            }
    std::sort(found.begin(), found.end());
    for (std::int32_t j : found) fresh.push_back(PairContactState{i, j, false, 0.0, Vec3::Zero(), 0.0});
  }
  // Carry the histories over: both lists are sorted by (owner, partner).
  std::size_t old = 0;
  for (PairContactState& p : fresh) {
    while (old < pairs_.size() &&
           (pairs_[old].owner < p.owner || (pairs_[old].owner == p.owner && pairs_[old].partner < p.partner)))
      ++old;
    if (old < pairs_.size() && pairs_[old].owner == p.owner && pairs_[old].partner == p.partner)
      p = pairs_[old];
  }
  spare_pairs_ = std::move(pairs_);
  pairs_ = std::move(fresh);

  std::vector<WallContactState> fresh_walls;
  std::size_t old_wall = 0;
  for (std::size_t ii = 0; ii < n; ++ii)
    for (std::size_t w = 0; w < walls.size(); ++w) {
      if (!(walls[w].gap(position[ii], radius[ii]) < skin_)) continue;
      WallContactState s{static_cast<std::int32_t>(ii), static_cast<std::int32_t>(w), false, 0.0,
                         Vec3::Zero(), 0.0};
      while (old_wall < wall_pairs_.size() &&
             (wall_pairs_[old_wall].particle < s.particle ||
              (wall_pairs_[old_wall].particle == s.particle && wall_pairs_[old_wall].wall < s.wall)))
        ++old_wall;
      if (old_wall < wall_pairs_.size() && wall_pairs_[old_wall].particle == s.particle &&
          wall_pairs_[old_wall].wall == s.wall)
        s = wall_pairs_[old_wall];
      fresh_walls.push_back(s);
    }
  wall_pairs_ = std::move(fresh_walls);
  reference_ = position;
  ++builds_;
}

std::vector<PairContactState> NeighbourList::brute_force(const Domain& domain, double skin,
                                                         const std::vector<Vec3>& position,
                                                         const std::vector<double>& radius) {
  std::vector<PairContactState> out;
  for (std::size_t i = 0; i < position.size(); ++i)
    for (std::size_t j = 0; j < position.size(); ++j) {
      if (i == j || !owns(radius[i], static_cast<std::int32_t>(i), radius[j], static_cast<std::int32_t>(j)))
        continue;
      Vec3 d = position[i] - position[j];
      domain.minimum_image(d);
      const double reach = radius[i] + radius[j] + skin;
      if (d.squaredNorm() < reach * reach)
        out.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), false, 0.0, Vec3::Zero(), 0.0});
    }
  return out;
}

}  // namespace carom
