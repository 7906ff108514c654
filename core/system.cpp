#include "system.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cell_grid.hpp"

namespace carom {

std::vector<Wall> box_walls(const Domain& domain) {
  std::vector<Wall> walls;
  const char* axis_name = "xyz";
  for (int k = 0; k < 3; ++k) {
    if (domain.periodic[k]) continue;
    Vec3 normal = Vec3::Zero();
    normal[k] = 1.0;
    walls.push_back(Wall::plane(std::string(1, axis_name[k]) + "_low", domain.lower, normal));
    walls.push_back(Wall::plane(std::string(1, axis_name[k]) + "_high", domain.upper, -normal));
  }
  return walls;
}

void validate_initial_state(const System& system, double overlap_tolerance) {
  const ParticleStore& p = system.particles;
  const std::size_t n = p.size();
  auto describe = [&](std::size_t i) {
    std::ostringstream out;
    out << "particle " << p.id[i] << " (species " << system.species.at(p.species[i]).name
        << ", centre " << p.position[i].transpose() << " m, radius " << p.radius[i] << " m)";
    return out.str();
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!p.position[i].allFinite() || !p.velocity[i].allFinite() || !p.spin[i].allFinite())
      throw std::invalid_argument(describe(i) + " has a non-finite position, velocity or spin");
    if (!(p.radius[i] > 0.0) || !(p.mass[i] > 0.0))
      throw std::invalid_argument(describe(i) + " must have positive radius and mass");
    for (int k = 0; k < 3; ++k) {
      // Walled axes: the wall check below is the one that matters (and carries the tolerance).
      const double slack = system.domain.periodic[k] ? 0.0 : overlap_tolerance * p.radius[i];
      if (p.position[i][k] < system.domain.lower[k] - slack || p.position[i][k] > system.domain.upper[k] + slack)
        throw std::invalid_argument(describe(i) + " lies outside the domain");
    }
    for (const Wall& wall : system.walls) {
      if (wall.gap(p.position[i], p.radius[i]) < -overlap_tolerance * p.radius[i])
        throw std::invalid_argument(describe(i) + " overlaps wall '" + wall.name + "' by " +
                                    std::to_string(-wall.gap(p.position[i], p.radius[i])) + " m");
    }
  }
  if (n == 0) return;
  HierarchicalGrid grid(system.domain, p.radius);
  std::vector<std::int32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) grid.insert(static_cast<std::int32_t>(i), p.position[i]);
  for (std::size_t i = 0; i < n; ++i) {
    grid.for_each_candidate(static_cast<std::int32_t>(i), [&](std::int32_t j) {
      if (static_cast<std::size_t>(j) < i) return;
      Vec3 dr = p.position[i] - p.position[j];
      system.domain.minimum_image(dr);
      const double contact = p.radius[i] + p.radius[j];
      const double allowed = contact * (1.0 - overlap_tolerance);
      if (dr.squaredNorm() < allowed * allowed)
        throw std::invalid_argument(describe(i) + " overlaps " + describe(static_cast<std::size_t>(j)) +
                                    " by " + std::to_string(contact - dr.norm()) + " m");
    });
  }
}

}  // namespace carom
