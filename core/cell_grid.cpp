#include "cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace carom {

HierarchicalGrid::HierarchicalGrid(const Domain& domain, const std::vector<double>& radius,
                                   double level_ratio)
    : domain_(domain) {
  std::vector<double> diameters;
  for (double a : radius) diameters.push_back(2.0 * a);
  std::sort(diameters.begin(), diameters.end(), std::greater<>());
  diameters.erase(std::unique(diameters.begin(), diameters.end()), diameters.end());
  if (diameters.empty()) diameters.push_back(domain.length().minCoeff() / 3.0);

  // Greedy levels, largest first.
  for (double d : diameters) {
    if (level_diameter_.empty() || d < level_ratio * level_diameter_.back())
      level_diameter_.push_back(d);
  }
  const Vec3 length = domain.length();
  for (double d : level_diameter_) {
    Level grid;
    for (int k = 0; k < 3; ++k) {
      int n = static_cast<int>(std::floor(length[k] / d));
      n = std::clamp(n, 1, 1 << 20);
      if (domain.periodic[k] && n < 3)
        throw std::invalid_argument(
            "periodic axis " + std::string(1, "xyz"[k]) + " is " + std::to_string(length[k]) +
            " m long; it must be at least 3 particle diameters (" + std::to_string(3 * d) + " m)");
      grid.cells[k] = n;
      grid.cell_size[k] = length[k] / n;
    }
    const double total = double(grid.cells[0]) * grid.cells[1] * grid.cells[2];
    if (total > 2.0e8)
      throw std::invalid_argument("the cell grid for diameter " + std::to_string(d) + " m needs " +
                                  std::to_string(total) + " cells; the domain is too large");
    grid.head.assign(static_cast<std::size_t>(total), -1);
    levels_.push_back(std::move(grid));
  }
  const std::size_t n = radius.size();
  next_.assign(n, -1);
  prev_.assign(n, -1);
  level_.assign(n, 0);
  coords_.assign(n, {0, 0, 0});
  for (std::size_t i = 0; i < n; ++i) {
    // The finest level whose nominal diameter still holds this particle.
    const double d = 2.0 * radius[i];
    int level = 0;
    for (int l = 0; l < static_cast<int>(level_diameter_.size()); ++l)
      if (level_diameter_[l] >= d) level = l;
    level_[i] = static_cast<std::uint8_t>(level);
    levels_[level].max_radius = std::max(levels_[level].max_radius, radius[i]);
  }
}

std::array<int, 3> HierarchicalGrid::cell_coordinates(int level, const Vec3& r) const {
  const Level& grid = levels_[level];
  std::array<int, 3> c{};
  for (int k = 0; k < 3; ++k) {
    const int idx = static_cast<int>(std::floor((r[k] - domain_.lower[k]) / grid.cell_size[k]));
    c[k] = std::clamp(idx, 0, grid.cells[k] - 1);
  }
  return c;
}

void HierarchicalGrid::link(std::int32_t i) {
  auto& head = levels_[level_[i]].head[flat_index(level_[i], coords_[i])];
  prev_[i] = -1;
  next_[i] = head;
  if (head >= 0) prev_[head] = i;
  head = i;
}

void HierarchicalGrid::unlink(std::int32_t i) {
  if (prev_[i] >= 0)
    next_[prev_[i]] = next_[i];
  else
    levels_[level_[i]].head[flat_index(level_[i], coords_[i])] = next_[i];
  if (next_[i] >= 0) prev_[next_[i]] = prev_[i];
  next_[i] = prev_[i] = -1;
}

void HierarchicalGrid::insert(std::int32_t i, const Vec3& r) {
  coords_[i] = cell_coordinates(level_[i], r);
  link(i);
}

Vec3 HierarchicalGrid::cross(std::int32_t i, int axis, int direction) {
  unlink(i);
  const Level& grid = levels_[level_[i]];
  Vec3 shift = Vec3::Zero();
  int idx = coords_[i][axis] + direction;
  if (idx < 0) {
    idx += grid.cells[axis];
    shift[axis] = domain_.length()[axis];
  } else if (idx >= grid.cells[axis]) {
    idx -= grid.cells[axis];
    shift[axis] = -domain_.length()[axis];
  }
  coords_[i][axis] = idx;
  link(i);
  return shift;
}

Vec3 HierarchicalGrid::cell_lower(std::int32_t i) const {
  const Level& grid = levels_[level_[i]];
  const auto& c = coords_[i];
  return {domain_.lower.x() + c[0] * grid.cell_size.x(), domain_.lower.y() + c[1] * grid.cell_size.y(),
          domain_.lower.z() + c[2] * grid.cell_size.z()};
}

Vec3 HierarchicalGrid::cell_upper(std::int32_t i) const {
  const Level& grid = levels_[level_[i]];
  const auto& c = coords_[i];
  auto edge = [&](int k) {
    return c[k] + 1 == grid.cells[k] ? domain_.upper[k]
                                     : domain_.lower[k] + (c[k] + 1) * grid.cell_size[k];
  };
  return {edge(0), edge(1), edge(2)};
}

bool HierarchicalGrid::is_outer_face(std::int32_t i, int axis, int direction) const {
  if (domain_.periodic[axis]) return false;
  const int idx = coords_[i][axis];
  return direction < 0 ? idx == 0 : idx + 1 == levels_[level_[i]].cells[axis];
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

HierarchicalGrid::AxisRange HierarchicalGrid::covering(int level, int k, double lo, double hi) const {
  const Level& grid = levels_[level];
  const int first = static_cast<int>(std::floor((lo - domain_.lower[k]) / grid.cell_size[k]));
  const int last = static_cast<int>(std::floor((hi - domain_.lower[k]) / grid.cell_size[k]));
  return clip(level, k, first, last);
}

}  // namespace carom
