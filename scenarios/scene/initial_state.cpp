// Building a scene's particles: listed ones, those read from a file, then each species' fill,
// then velocities; then, optionally, a settling run.
#include <cmath>

#include "scenarios/scene/fill_capacity.hpp"
#include "scenarios/scene/initial_file.hpp"
#include "scenarios/scene/placement.hpp"
#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/settling.hpp"
#include "scenarios/scene/state_bounds.hpp"

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
      if (counts[s] == 0 && fill->value > 0.0)
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
    if (counts[s] == 0 && fill->value > 0.0)
      throw SceneError(fill->where + ": species \"" + species[s].name + "\": mass_fraction " +
                       format_number(fill->value) + " is less than one particle");
  }
  return counts;
}

namespace {
/// Says where particles came from in a validation message: "[[particles]] entry at file:line"
/// after each listed particle's id, "row k of initial.from_file" after each particle read from
/// a file (ids [first_from_file, first_from_file + from_file)).
std::string with_sources(const std::string& message, const Scene& scene, std::size_t first_from_file,
                         std::size_t from_file) {
  std::string out = message;
  auto annotate = [&](std::size_t id, const std::string& source) {
    const std::string tag = "particle " + std::to_string(id) + " (";
    const std::size_t at = out.find(tag);
    if (at != std::string::npos) out.insert(at + tag.size(), source + ", ");
  };
  for (std::size_t i = 0; i < scene.listed.size(); ++i) annotate(i, "[[particles]] entry at " + scene.listed[i].where);
  for (std::size_t k = 0; k < from_file; ++k)
    annotate(first_from_file + k, "row " + std::to_string(k) + " of initial.from_file (" + scene.from_file->where + ")");
  return out;
}
/// Refuses a temperature or an rms velocity that would give the fill's particles speeds above
/// kMaxSpeed (the lightest filled species moves fastest: sqrt(3 T / m)).
void check_fill_speeds(const Scene& scene, const std::vector<std::size_t>& counts) {
  for (std::size_t s = 0; s < counts.size(); ++s) {
    if (counts[s] == 0) continue;
    const double mass = scene.system.species[s].mass();
    const double speed = scene.rms_velocity > 0 ? scene.rms_velocity : std::sqrt(3.0 * scene.temperature / mass);
    if (!(speed <= kMaxSpeed))
      throw SceneError(scene.file + ": initial." + (scene.rms_velocity > 0 ? "rms_velocity" : "temperature") +
                       ": gives species \"" + scene.system.species[s].name + "\" an rms speed of " + format_number(speed) +
                       " m/s, above the bound of " + format_number(kMaxSpeed) +
                       " m/s on any particle's speed (no granular flow comes near it; check the units: temperature is "
                       "m <v_x^2> in J)");
  }
}

/// Refuses a particle whose velocity or spin is not finite or faster than kMaxSpeed.
void check_particle_speeds(const Scene& scene, std::size_t first_from_file, std::size_t from_file) {
  const ParticleStore& p = scene.system.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double speed = p.velocity[i].norm(), surface = p.spin[i].norm() * p.radius[i];
    if (speed <= kMaxSpeed && surface <= kMaxSpeed) continue;
    const std::string what = speed <= kMaxSpeed ? "spins with a surface speed |spin| r of " + format_number(surface)
                                                 : "moves at " + format_number(speed);
    throw SceneError(scene.file + ": initial state: " +
                     with_sources("particle " + std::to_string(i) + " (species \"" + scene.system.species[p.species[i]].name +
                                      "\") " + what + " m/s: not finite or above the bound of " + format_number(kMaxSpeed) +
                                      " m/s on any particle's speed",
                                  scene, first_from_file, from_file));
  }
}

}  // namespace

void build_initial_state(Scene& scene, const volatile std::sig_atomic_t* stop) {
  System& system = scene.system;
  system.particles = ParticleStore{};
  const std::vector<std::size_t> counts = fill_counts(scene);
  check_fill_capacities(scene, counts);  // before anything is allocated for them
  check_fill_speeds(scene, counts);
  std::vector<double> radii;
  for (const ListedParticle& p : scene.listed) radii.push_back(system.species[p.species].radius());
  std::vector<FileParticle> from_file;
  if (scene.from_file) from_file = read_initial_file(scene);
  for (const FileParticle& p : from_file) radii.push_back(system.species[p.species].radius());
  for (std::size_t s = 0; s < counts.size(); ++s) radii.insert(radii.end(), counts[s], system.species[s].radius());

  // Listed particles go in as written; validate_initial_state names any overlap.
  for (const ListedParticle& p : scene.listed) system.add_particle(p.species, p.position, p.velocity, p.spin);
  // Particles from a file keep their velocities and spins; fills are placed around them.
  const std::size_t first_from_file = system.particles.size();
  for (const FileParticle& p : from_file) system.add_particle(p.species, p.position, p.velocity, p.spin);
  const std::size_t first_filled = system.particles.size();
  if (first_filled < radii.size()) {
    std::optional<Placer> placer;
    try {
      placer.emplace(system, radii);
    } catch (const std::invalid_argument& e) {
      throw SceneError(scene.file + ": domain: " + e.what());
    }
    placer->set_stop_flag(stop);
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
      if (placer->stopped())
        throw InterruptedBeforeStart(
            "interrupted while the particles were placed, before the run's t = 0: "
            "nothing was written; run the same command again to start over");
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
  // Placed and listed particles must not touch at all; a state read from a run may overlap by
  // round-off, which the engine itself tolerates (kContactTolerance).
  // Soft spheres overlap at their contacts: a state of a soft-sphere run may overlap by as much
  // as the method itself allows (half of max_overlap of the contact distance bounds
  // max_overlap of the smaller radius).
  const bool soft = scene.method.kind == MethodKind::SoftSphere;
  const double run_tolerance = soft ? 0.5 * scene.method.soft_sphere.max_overlap : kContactTolerance;
  const double tolerance = from_file.empty() ? 0.0 : run_tolerance;
  check_particle_speeds(scene, first_from_file, from_file.size());
  try {
    validate_initial_state(system, tolerance);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": initial state: " + with_sources(e.what(), scene, first_from_file, from_file.size()));
  }
  if (scene.settle_time <= 0.0) return;
  settle(scene, stop);
  try {
    validate_initial_state(system, run_tolerance);
  } catch (const std::invalid_argument& e) {  // an engine invariant broken: report it plainly
    throw SceneError(scene.settle_where + ": initial.settle_time: the settled state is not valid: " + e.what());
  }
}

}  // namespace carom
