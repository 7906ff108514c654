#include "scenarios/scene/granular_gas.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/cell_grid.hpp"
#include "core/rng.hpp"

namespace carom {

namespace {
void set_maxwellian_velocities(System& system, double temperature, Rng& rng) {
  ParticleStore& p = system.particles;
  const std::size_t n = p.size();
  Vec3 momentum = Vec3::Zero();
  double mass = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    p.velocity[i] = rng.normal3() * std::sqrt(temperature / p.mass[i]);
    momentum += p.mass[i] * p.velocity[i];
    mass += p.mass[i];
  }
  double kinetic = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    p.velocity[i] -= momentum / mass;
    kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  }
  if (n < 2 || kinetic <= 0.0) return;
  const double scale = std::sqrt(1.5 * (n - 1) * temperature / kinetic);
  for (std::size_t i = 0; i < n; ++i) p.velocity[i] *= scale;
}
}  // namespace

System make_granular_gas(const GranularGasSpec& spec) {
  if (!(spec.volume_fraction > 0.0 && spec.volume_fraction < 0.74))
    throw std::invalid_argument("volume fraction must be in (0, 0.74)");
  System system;
  system.species.push_back(Species{"large", spec.diameter, spec.density});
  const bool mixture = spec.fines_number_fraction > 0.0 && spec.fines_diameter_ratio != 1.0;
  if (mixture)
    system.species.push_back(Species{"fines", spec.diameter * spec.fines_diameter_ratio, spec.density});
  system.domain.periodic = {true, true, true};
  ContactLaw law;
  law.restitution = spec.restitution;
  system.materials = MaterialTable(system.species.size(), 0, law, law);
  Rng rng(spec.seed);

  if (!mixture) {
    const auto k = static_cast<std::size_t>(std::max(1.0, std::round(std::cbrt(spec.count / 4.0))));
    const std::size_t n = 4 * k * k * k;
    const double volume = n * system.species[0].volume() / spec.volume_fraction;
    const double edge = std::cbrt(volume), cell = edge / k;
    system.domain.upper = Vec3::Constant(edge);
    const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    for (std::size_t x = 0; x < k; ++x)
      for (std::size_t y = 0; y < k; ++y)
        for (std::size_t z = 0; z < k; ++z)
          for (const auto& b : basis)
            system.add_particle(0, Vec3((x + b[0] + 0.25) * cell, (y + b[1] + 0.25) * cell, (z + b[2] + 0.25) * cell),
                                Vec3::Zero());
  } else {
    const std::size_t fines = static_cast<std::size_t>(std::round(spec.count * spec.fines_number_fraction));
    const std::size_t large = spec.count - fines;
    const double volume = (large * system.species[0].volume() + fines * system.species[1].volume()) /
                          spec.volume_fraction;
    const double edge = std::cbrt(volume);
    system.domain.upper = Vec3::Constant(edge);
    std::vector<double> radius(large, system.species[0].radius());
    radius.resize(spec.count, system.species[1].radius());
    HierarchicalGrid grid(system.domain, radius);
    for (std::size_t i = 0; i < spec.count; ++i) {
      const std::uint32_t s = i < large ? 0 : 1;
      const double a = radius[i];
      for (std::size_t attempt = 0;; ++attempt) {
        if (attempt > 100000)
          throw std::runtime_error("random insertion failed: the volume fraction is too high for a mixture");
        const Vec3 r(rng.uniform(0, edge), rng.uniform(0, edge), rng.uniform(0, edge));
        system.add_particle(s, r, Vec3::Zero());
        const auto id = static_cast<std::int32_t>(i);
        grid.insert(id, r);
        bool overlap = false;
        grid.for_each_candidate(id, [&](std::int32_t j) {
          Vec3 dr = r - system.particles.position[j];
          system.domain.minimum_image(dr);
          const double contact = a + radius[j];
          if (dr.squaredNorm() < contact * contact) overlap = true;
        });
        if (!overlap) break;
        grid.remove(id);
        system.particles.pop_back();
      }
    }
  }
  set_maxwellian_velocities(system, spec.temperature, rng);
  return system;
}

}  // namespace carom
