#include "scenarios/analysis/local_fields.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/nan.hpp"
#include "scenarios/analysis/enskog.hpp"

namespace carom {

namespace {
}  // namespace

double LocalFields::number_density(std::size_t cell, std::size_t species) const {
  if (!(open_volume[cell] > 0.0)) return kNaN;
  return double(count[at(cell, species)]) / open_volume[cell];
}

double LocalFields::solid_fraction(std::size_t cell) const {
  if (!(open_volume[cell] > 0.0)) return kNaN;
  double volume = 0.0;
  for (std::size_t s = 0; s < species_count; ++s) volume += solid_volume[at(cell, s)];
  return volume / open_volume[cell];
}

LocalFields local_fields(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                         const std::vector<std::uint32_t>& species,
                         const std::vector<double>& radii, std::size_t species_count,
                         const SampleGrid& grid, const std::vector<double>& open_volume) {
  const std::size_t n = positions.size();
  if (velocities.size() != n || species.size() != n || radii.size() != n)
    throw std::invalid_argument(
        "local_fields: positions, velocities, species and radii differ in length");
  grid.check();
  if (!open_volume.empty() && open_volume.size() != grid.size())
    throw std::invalid_argument("local_fields: open_volume has " +
                                std::to_string(open_volume.size()) + " entries for " +
                                std::to_string(grid.size()) + " cells");
  for (std::uint32_t s : species)
    if (s >= species_count)
      throw std::invalid_argument("local_fields: species id " + std::to_string(s) + " but only " +
                                  std::to_string(species_count) + " species");

  LocalFields fields;
  fields.grid = grid;
  fields.species_count = species_count;
  fields.open_volume =
      open_volume.empty() ? std::vector<double>(grid.size(), grid.cell_volume()) : open_volume;
  const std::size_t slots = grid.size() * species_count;
  fields.count.assign(slots, 0);
  fields.solid_volume.assign(slots, 0.0);
  fields.mean_velocity.assign(slots, Vec3::Zero());
  fields.granular_temperature.assign(slots, 0.0);

  std::vector<double> diameter_sum(species_count, 0.0);
  std::vector<std::size_t> species_total(species_count, 0);
  std::vector<int> cell_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    diameter_sum[species[i]] += 2.0 * radii[i];
    ++species_total[species[i]];
    cell_of[i] = grid.cell_of(positions[i]);
    if (cell_of[i] < 0) continue;
    const std::size_t slot = fields.at(std::size_t(cell_of[i]), species[i]);
    ++fields.count[slot];
    fields.solid_volume[slot] += 4.0 / 3.0 * std::numbers::pi * radii[i] * radii[i] * radii[i];
    fields.mean_velocity[slot] += velocities[i];
  }
  fields.species_diameter.assign(species_count, 0.0);
  for (std::size_t s = 0; s < species_count; ++s)
    if (species_total[s] > 0)
      fields.species_diameter[s] = diameter_sum[s] / double(species_total[s]);

  for (std::size_t slot = 0; slot < slots; ++slot)
    if (fields.count[slot] > 0) fields.mean_velocity[slot] /= double(fields.count[slot]);
  // Second pass: fluctuations about the species' local mean velocity (no cancellation error).
  for (std::size_t i = 0; i < n; ++i) {
    if (cell_of[i] < 0) continue;
    const std::size_t slot = fields.at(std::size_t(cell_of[i]), species[i]);
    fields.granular_temperature[slot] += (velocities[i] - fields.mean_velocity[slot]).squaredNorm();
  }
  for (std::size_t slot = 0; slot < slots; ++slot) {
    if (fields.count[slot] > 0) {
      fields.granular_temperature[slot] /= 3.0 * double(fields.count[slot]);
    } else {
      fields.mean_velocity[slot] = Vec3::Constant(kNaN);
      fields.granular_temperature[slot] = kNaN;
    }
  }
  return fields;
}

std::vector<double> species_granular_temperature(const LocalFields& fields) {
  std::vector<double> weighted(fields.species_count, 0.0), weight(fields.species_count, 0.0);
  for (std::size_t cell = 0; cell < fields.grid.size(); ++cell)
    for (std::size_t s = 0; s < fields.species_count; ++s) {
      const std::size_t slot = fields.at(cell, s);
      if (fields.count[slot] < 2) continue;
      weighted[s] += double(fields.count[slot]) * fields.granular_temperature[slot];
      weight[s] += double(fields.count[slot]);
    }
  std::vector<double> temperature(fields.species_count, kNaN);
  for (std::size_t s = 0; s < fields.species_count; ++s)
    if (weight[s] > 0.0) temperature[s] = weighted[s] / weight[s];
  return temperature;
}

std::vector<double> cell_collision_frequencies(const LocalFields& fields, std::size_t cell,
                                               const std::vector<double>& fallback_temperature,
                                               double impact_speed) {
  const std::size_t S = fields.species_count;
  std::vector<double> frequency(S * S, kNaN);
  if (!(fields.open_volume[cell] > 0.0) || !(fields.solid_fraction(cell) < 1.0)) return frequency;

  std::vector<MixtureComponent> mixture(S);
  std::vector<double> theta(S);
  for (std::size_t s = 0; s < S; ++s) {
    mixture[s].number_density = fields.number_density(cell, s);
    mixture[s].diameter = fields.species_diameter[s];
    const std::size_t slot = fields.at(cell, s);
    const double fallback =
        s < fallback_temperature.size() && std::isfinite(fallback_temperature[s])
            ? fallback_temperature[s]
            : 0.0;
    theta[s] = fields.count[slot] >= 2 ? fields.granular_temperature[slot] : fallback;
  }
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t t = 0; t < S; ++t) {
      const double n_t = mixture[t].number_density;
      if (n_t == 0.0) {
        frequency[s * S + t] = 0.0;
        continue;
      }
      const double d = 0.5 * (mixture[s].diameter + mixture[t].diameter);
      const double mean_relative_speed = std::sqrt(8.0 * (theta[s] + theta[t]) / std::numbers::pi);
      frequency[s * S + t] = n_t * std::numbers::pi * d * d * contact_value(mixture, s, t) *
                             mean_relative_speed *
                             impact_share(impact_speed, theta[s] + theta[t]);
    }
  return frequency;
}

double impact_share(double impact_speed, double relative_variance) {
  if (impact_speed == 0.0) return 1.0;
  if (!(relative_variance > 0.0)) return 0.0;
  return std::exp(-impact_speed * impact_speed / (2.0 * relative_variance));
}

std::vector<double> kinetic_collision_frequencies(const LocalFields& fields, double impact_speed) {
  const std::size_t S = fields.species_count;
  if (S == 0) return {};
  const std::vector<double> fallback = species_granular_temperature(fields);
  std::vector<double> weighted(S * S, 0.0), weight(S, 0.0);
  for (std::size_t cell = 0; cell < fields.grid.size(); ++cell) {
    const std::vector<double> frequency =
        cell_collision_frequencies(fields, cell, fallback, impact_speed);
    if (std::isnan(frequency[0])) continue;  // all NaN or none
    for (std::size_t s = 0; s < S; ++s) {
      const double count = double(fields.count[fields.at(cell, s)]);
      if (count == 0.0) continue;
      weight[s] += count;
      for (std::size_t t = 0; t < S; ++t) weighted[s * S + t] += count * frequency[s * S + t];
    }
  }
  std::vector<double> average(S * S, kNaN);
  for (std::size_t s = 0; s < S; ++s)
    if (weight[s] > 0.0)
      for (std::size_t t = 0; t < S; ++t) average[s * S + t] = weighted[s * S + t] / weight[s];
  return average;
}

}  // namespace carom
