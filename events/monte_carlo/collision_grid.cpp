#include "events/monte_carlo/collision_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace carom {

CollisionGrid::CollisionGrid(const Domain& domain, double cell_size, std::size_t species)
    : domain_(domain), species_(species) {
  if (!(cell_size > 0.0)) throw std::invalid_argument("the collision cell size must be positive");
  const Vec3 length = domain.length();
  for (int k = 0; k < 3; ++k) {
    cells_[k] = std::max(1, static_cast<int>(std::floor(length[k] / cell_size)));
    size_[k] = length[k] / cells_[k];
  }
  sums_.assign(cell_count() * species_, Sums{});
}

void CollisionGrid::clear() { std::fill(sums_.begin(), sums_.end(), Sums{}); }

std::int32_t CollisionGrid::cell_of(const Vec3& r) const {
  std::int32_t flat = 0, stride = 1;
  for (int k = 0; k < 3; ++k) {
    // Bounded before the conversion: a position far outside the box (a run blowing up, which
    // the run's speed bound then stops) must not overflow the int; NaN goes to cell 0.
    const double x = std::clamp(std::floor((r[k] - domain_.lower[k]) / size_[k]), -1e9, 1e9);
    int c = std::isnan(x) ? 0 : static_cast<int>(x);
    if (domain_.periodic[k])
      c = ((c % cells_[k]) + cells_[k]) % cells_[k];
    else
      c = std::clamp(c, 0, cells_[k] - 1);
    flat += c * stride;
    stride *= cells_[k];
  }
  return flat;
}

std::int32_t CollisionGrid::add(const Vec3& r, std::uint32_t s, double a, const Vec3& v, const Vec3& w) {
  const std::int32_t cell = cell_of(r);
  Sums& sum = sums_[cell * species_ + s];
  sum.count += 1.0;
  sum.radius += a;
  sum.radius_squared += a * a;
  sum.radius_cubed += a * a * a;
  sum.velocity += v;
  sum.velocity_squared += v.cwiseProduct(v);
  sum.spin += w;
  return cell;
}

PartnerStatistics CollisionGrid::partners(std::int32_t cell, std::uint32_t s,
                                          const OwnContribution* own) const {
  Sums sum = sums(cell, s);
  if (own != nullptr && own->species == s) {
    sum.count -= 1.0;
    sum.radius -= own->radius;
    sum.velocity -= own->velocity;
    sum.velocity_squared -= own->velocity.cwiseProduct(own->velocity);
    sum.spin -= own->spin;
  }
  PartnerStatistics p;
  p.count = sum.count;
  if (sum.count < 0.5) return p;
  p.number_density = sum.count / cell_volume();
  p.mean_radius = sum.radius / sum.count;
  p.mean_velocity = sum.velocity / sum.count;
  p.mean_spin = sum.spin / sum.count;
  for (int k = 0; k < 3; ++k) {
    // sum (v - <v>)^2 = sum v^2 - count <v>^2; round-off can make it slightly negative.
    const double scatter = sum.velocity_squared[k] - sum.count * p.mean_velocity[k] * p.mean_velocity[k];
    p.velocity_std[k] = std::sqrt(std::max(0.0, scatter / sum.count));
  }
  return p;
}

void CollisionGrid::list_members(const std::vector<std::int32_t>& cell,
                                 const std::vector<std::uint32_t>& species,
                                 const std::vector<Vec3>& velocity) {
  const std::size_t lists = cell_count() * species_;
  member_begin_.assign(lists + 1, 0);
  for (std::size_t i = 0; i < cell.size(); ++i)
    ++member_begin_[static_cast<std::size_t>(cell[i]) * species_ + species[i] + 1];
  for (std::size_t k = 0; k < lists; ++k) member_begin_[k + 1] += member_begin_[k];
  members_.resize(cell.size());
  std::vector<std::size_t> next(member_begin_.begin(), member_begin_.end() - 1);
  largest_deviation_.assign(lists, 0.0);
  for (std::size_t i = 0; i < cell.size(); ++i) {
    const std::size_t k = static_cast<std::size_t>(cell[i]) * species_ + species[i];
    members_[next[k]++] = static_cast<std::uint32_t>(i);
    const double deviation = (velocity[i] - mean_velocity(cell[i], species[i])).norm();
    largest_deviation_[k] = std::max(largest_deviation_[k], deviation);
  }
}

double CollisionGrid::solid_fraction(std::int32_t cell) const {
  double volume = 0.0;
  for (std::size_t s = 0; s < species_; ++s) volume += sums(cell, static_cast<std::uint32_t>(s)).radius_cubed;
  return 4.0 / 3.0 * std::numbers::pi * volume / cell_volume();
}

double CollisionGrid::xi2(std::int32_t cell) const {
  double diameter_squared = 0.0;
  for (std::size_t s = 0; s < species_; ++s)
    diameter_squared += 4.0 * sums(cell, static_cast<std::uint32_t>(s)).radius_squared;
  return std::numbers::pi / 6.0 * diameter_squared / cell_volume();
}

}  // namespace carom
