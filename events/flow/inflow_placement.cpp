#include "events/flow/inflow_placement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace carom {

namespace {
/// Most cells a placer allocates (at cells of one contact distance a slab of a wide duct would
/// need millions); beyond it the cells grow. Allocated once per inflow and flow step.
constexpr double kMaxCells = 1 << 16;
}  // namespace

SlabPlacer::SlabPlacer(const Box& centres, double radius, double max_radius, const Domain& domain,
                       const std::vector<Wall>& walls)
    : centres_(centres),
      radius_(radius),
      reach_(radius + std::max(radius, max_radius)),
      domain_(domain),
      walls_(walls) {
  grid_.lower = centres.lower.array() - reach_;
  grid_.upper = centres.upper.array() + reach_;
  const Vec3 extent = grid_.upper - grid_.lower;
  double n[3], total = 1.0;
  for (int k = 0; k < 3; ++k) {
    n[k] = std::max(1.0, std::floor(extent[k] / reach_));
    total *= n[k];
  }
  const double shrink = total > kMaxCells ? std::cbrt(kMaxCells / total) : 1.0;
  for (int k = 0; k < 3; ++k) {
    cells_[k] = static_cast<int>(std::max(1.0, std::floor(n[k] * shrink)));
    cell_size_[k] = extent[k] / cells_[k];
  }
  head_.assign(std::size_t(cells_[0]) * cells_[1] * cells_[2], -1);
}

std::size_t SlabPlacer::cell_of(const Vec3& r) const {
  std::size_t flat = 0;
  for (int k = 2; k >= 0; --k) {
    const int c = std::clamp(static_cast<int>(std::floor((r[k] - grid_.lower[k]) / cell_size_[k])),
                             0, cells_[k] - 1);
    flat = flat * cells_[k] + c;
  }
  return flat;
}

void SlabPlacer::add(const Vec3& r, double a) {
  if (a + radius_ > reach_ * (1.0 + 1e-12))
    throw std::logic_error("SlabPlacer: a sphere larger than the radius it was built for");
  // Fold into the box on periodic axes, then every image (shifts of -L, 0, +L per periodic
  // axis) that lies in the grid: those are the only ones a new sphere can touch.
  Vec3 folded = r;
  int shifts[3] = {1, 1, 1};
  const Vec3 length = domain_.length();
  for (int k = 0; k < 3; ++k) {
    if (!domain_.periodic[k]) continue;
    shifts[k] = 3;
    folded[k] = domain_.lower[k] + std::fmod(folded[k] - domain_.lower[k], length[k]);
    if (folded[k] < domain_.lower[k]) folded[k] += length[k];
  }
  static constexpr double kShift[3] = {0.0, 1.0, -1.0};
  for (int sz = 0; sz < shifts[2]; ++sz)
    for (int sy = 0; sy < shifts[1]; ++sy)
      for (int sx = 0; sx < shifts[0]; ++sx) {
        const Vec3 image = folded + Vec3(kShift[sx] * length.x(), kShift[sy] * length.y(),
                                         kShift[sz] * length.z());
        if (!grid_.contains(image)) continue;
        const std::size_t cell = cell_of(image);
        const auto index = static_cast<std::int32_t>(position_.size());
        position_.push_back(image);
        sphere_radius_.push_back(a);
        next_.push_back(head_[cell]);
        head_[cell] = index;
      }
}

bool SlabPlacer::free(const Vec3& r) const {
  for (int k = 0; k < 3; ++k)
    if (!domain_.periodic[k] &&
        (r[k] - radius_ < domain_.lower[k] || r[k] + radius_ > domain_.upper[k]))
      return false;
  for (const Wall& wall : walls_)
    if (!(wall.gap(r, radius_) >= 0.0)) return false;
  int first[3], last[3];
  for (int k = 0; k < 3; ++k) {
    first[k] =
        std::clamp(static_cast<int>(std::floor((r[k] - reach_ - grid_.lower[k]) / cell_size_[k])),
                   0, cells_[k] - 1);
    last[k] =
        std::clamp(static_cast<int>(std::floor((r[k] + reach_ - grid_.lower[k]) / cell_size_[k])),
                   0, cells_[k] - 1);
  }
  for (int z = first[2]; z <= last[2]; ++z)
    for (int y = first[1]; y <= last[1]; ++y)
      for (int x = first[0]; x <= last[0]; ++x)
        for (std::int32_t j = head_[x + std::size_t(cells_[0]) * (y + std::size_t(cells_[1]) * z)];
             j >= 0; j = next_[j])
          if (!((r - position_[j]).norm() - (radius_ + sphere_radius_[j]) >= 0.0)) return false;
  return true;
}

bool SlabPlacer::place(Rng& rng, int attempts, Vec3& found) {
  for (int attempt = 0; attempt < attempts; ++attempt) {
    Vec3 r;
    for (int k = 0; k < 3; ++k) r[k] = rng.uniform(centres_.lower[k], centres_.upper[k]);
    if (free(r)) {
      add(r, radius_);
      found = r;
      return true;
    }
    ++failed_tries_;
  }
  return false;
}

}  // namespace carom
