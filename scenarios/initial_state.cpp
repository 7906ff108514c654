// Building a scene's particles: listed ones, then each species' fill, then velocities.
#include <cmath>

#include "placement.hpp"
#include "scene.hpp"

namespace carom {

std::vector<std::size_t> fill_counts(const Scene& scene) {
  const auto& species = scene.system.species;
  std::vector<std::size_t> counts(species.size(), 0);
  double fixed_mass = 0.0, fraction_sum = 0.0;
  for (const ListedParticle& p : scene.listed) fixed_mass += species[p.species].mass();
  for (std::size_t s = 0; s < species.size(); ++s) {
    const auto& fill = scene.fills[s];
    if (!fill) continue;
    if (fill->amount == Fill::Amount::Count) {
      counts[s] = static_cast<std::size_t>(fill->value);
    } else if (fill->amount == Fill::Amount::VolumeFraction) {
      const double volume = scene.regions[fill->region].volume();
      counts[s] = static_cast<std::size_t>(std::llround(fill->value * volume / species[s].volume()));
      if (counts[s] == 0)
        throw SceneError(fill->where + ": species \"" + species[s].name + "\": volume_fraction " +
                         format_number(fill->value) + " of region \"" + scene.regions[fill->region].name +
                         "\" is less than one particle");
    } else {
      fraction_sum += fill->value;
      continue;
    }
    fixed_mass += static_cast<double>(counts[s]) * species[s].mass();
  }
  if (fraction_sum == 0.0) return counts;
  if (fraction_sum >= 1.0 || fixed_mass <= 0.0) {
    std::string where;
    for (std::size_t s = 0; s < species.size(); ++s)
      if (scene.fills[s] && scene.fills[s]->amount == Fill::Amount::MassFraction) where = scene.fills[s]->where;
    throw SceneError(where + ": mass fractions add up to " + format_number(fraction_sum) +
                     (fixed_mass <= 0.0 ? " and no species is given by count or volume_fraction"
                                        : ", which leaves nothing for the other species") +
                     ": a mass fraction is of all solids, so at least one species must be given by count or "
                     "volume_fraction and the fractions must sum to less than 1");
  }
  const double total_mass = fixed_mass / (1.0 - fraction_sum);
  for (std::size_t s = 0; s < species.size(); ++s) {
    const auto& fill = scene.fills[s];
    if (!fill || fill->amount != Fill::Amount::MassFraction) continue;
    counts[s] = static_cast<std::size_t>(std::llround(fill->value * total_mass / species[s].mass()));
    if (counts[s] == 0)
      throw SceneError(fill->where + ": species \"" + species[s].name + "\": mass_fraction " +
                       format_number(fill->value) + " is less than one particle");
  }
  return counts;
}

namespace {
/// Adds "(defined at file:line)" after each listed particle's id in a validation message.
std::string with_listed_lines(const std::string& message, const Scene& scene) {
  std::string out = message;
  for (std::size_t i = 0; i < scene.listed.size(); ++i) {
    const std::string tag = "particle " + std::to_string(i) + " (";
    const std::size_t at = out.find(tag);
    if (at != std::string::npos)
      out.insert(at + tag.size(), "[[particles]] entry at " + scene.listed[i].where + ", ");
  }
  return out;
}
}  // namespace

void build_initial_state(Scene& scene) {
  System& system = scene.system;
  system.particles = ParticleStore{};
  const std::vector<std::size_t> counts = fill_counts(scene);
  std::vector<double> radii;
  for (const ListedParticle& p : scene.listed) radii.push_back(system.species[p.species].radius());
  for (std::size_t s = 0; s < counts.size(); ++s) radii.insert(radii.end(), counts[s], system.species[s].radius());

  // Listed particles go in as written; validate_initial_state names any overlap.
  for (const ListedParticle& p : scene.listed) system.add_particle(p.species, p.position, p.velocity, p.spin);
  const std::size_t first_filled = system.particles.size();
  if (first_filled < radii.size()) {
    std::optional<Placer> placer;
    try {
      placer.emplace(system, radii);
    } catch (const std::invalid_argument& e) {
      throw SceneError(scene.file + ": domain: " + e.what());
    }
    Rng rng(scene.seed);
    for (std::size_t s = 0; s < counts.size(); ++s) {
      if (counts[s] == 0) continue;
      const Fill& fill = *scene.fills[s];
      const Region& region = scene.regions[fill.region];
      const auto index = static_cast<std::uint32_t>(s);
      const std::size_t placed =
          fill.arrangement == Fill::Arrangement::Random
              ? placer->random(index, counts[s], region.lower, region.upper, rng)
              : placer->lattice(index, counts[s], region.lower, region.upper, fill.arrangement == Fill::Arrangement::Fcc);
      if (placed < counts[s]) {
        const double phi = static_cast<double>(counts[s]) * system.species[s].volume() / region.volume();
        throw SceneError(
            fill.where + ": species \"" + system.species[s].name + "\": placed only " + std::to_string(placed) + " of " +
            std::to_string(counts[s]) + " particles in region \"" + region.name + "\" (this species alone fills " +
            format_number(phi) + " of its volume, on top of what is already there). " +
            (fill.arrangement == Fill::Arrangement::Random
                 ? "Random insertion jams near a volume fraction of 0.3-0.38; use arrangement = \"fcc\" (up to 0.74), "
                   "a larger region, or fewer particles."
                 : "The region holds fewer lattice sites; use a larger region or fewer particles."));
      }
    }
    set_maxwellian(system, first_filled, scene.temperature, scene.rms_velocity, rng);
  }
  try {
    validate_initial_state(system);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": initial state: " + with_listed_lines(e.what(), scene));
  }
}

}  // namespace carom
