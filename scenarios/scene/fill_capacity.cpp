#include "scenarios/scene/fill_capacity.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "scenarios/scene/placement.hpp"

namespace carom {

namespace {
/// Random close packing of equal spheres: the most a random fill can take of its region.
constexpr double kRandomCloseFraction = 0.64;
/// The densest packing of equal spheres, pi / sqrt(18) (Kepler's conjecture, proved by Hales
/// 2005): no arrangement of equal spheres fills more of a region.
constexpr double kDensestEqualFraction = 0.74048048969306104;

/// Four significant digits: derived numbers in a message.
std::string short_number(double x) {
  std::ostringstream out;
  out.precision(4);
  out << x;
  return out.str();
}
}  // namespace

std::size_t fill_capacity(const Scene& scene, std::size_t s) {
  const Fill& fill = *scene.fills.at(s);
  const Region& region = scene.regions[fill.region];
  const Species& species = scene.system.species[s];
  if (fill.arrangement == Fill::Arrangement::Random)
    return static_cast<std::size_t>(std::min(1e18, std::floor(kRandomCloseFraction * region.volume() / species.volume())));
  // The lattice at contact spacing: ask for more sites than any fill can have.
  const LatticePlan plan = plan_lattice(scene.system.domain, species.radius(), std::size_t{1} << 62, region.lower,
                                        region.upper, fill.arrangement == Fill::Arrangement::Fcc);
  return plan.sites;
}

void check_fill_capacities(const Scene& scene, const std::vector<std::size_t>& counts) {
  for (std::size_t s = 0; s < counts.size(); ++s) {
    if (counts[s] == 0 || !scene.fills[s]) continue;
    const Fill& fill = *scene.fills[s];
    const Region& region = scene.regions[fill.region];
    const Species& species = scene.system.species[s];
    const bool random = fill.arrangement == Fill::Arrangement::Random;
    // A lattice fill that its own spacing can hold needs no search for the capacity.
    if (!random && plan_lattice(scene.system.domain, species.radius(), counts[s], region.lower, region.upper,
                                fill.arrangement == Fill::Arrangement::Fcc)
                           .sites >= counts[s])
      continue;
    const std::size_t capacity = fill_capacity(scene, s);
    if (counts[s] <= capacity) continue;
    const double phi = static_cast<double>(counts[s]) * species.volume() / region.volume();
    std::string message = fill.amount_where + ": " + fill.amount_key + " = " + fill.amount_text + " asks for " +
                          std::to_string(counts[s]) + " particles of species \"" + species.name + "\" (d = " +
                          format_number(species.diameter) + " m), " + short_number(phi) +
                          " of the volume of region \"" + region.name + "\" (" + short_number(region.volume()) +
                          " m^3); ";
    if (random)
      message += "random insertion can never fill more than " + format_number(kRandomCloseFraction) +
                 " of a region (random close packing; in practice it jams near 0.38), so at most " +
                 std::to_string(capacity) + " fit. Use fewer particles (at most " + std::to_string(capacity) +
                 "), a larger region, or arrangement = \"fcc\" (up to 0.74)";
    else
      message += std::string("the ") + (fill.arrangement == Fill::Arrangement::Fcc ? "fcc" : "cubic") +
                 " lattice at contact spacing has " + std::to_string(capacity) + " sites there, so at most " +
                 std::to_string(capacity) + " fit. Use fewer particles (at most " + std::to_string(capacity) +
                 ") or a larger region";
    throw SceneError(message);
  }
  check_shared_regions(scene, counts);
}

void check_shared_regions(const Scene& scene, const std::vector<std::size_t>& counts) {
  for (std::size_t r = 0; r < scene.regions.size(); ++r) {
    std::vector<std::size_t> sharing;
    for (std::size_t s = 0; s < counts.size(); ++s)
      if (counts[s] > 0 && scene.fills[s] && scene.fills[s]->region == r) sharing.push_back(s);
    if (sharing.size() < 2) continue;
    const Region& region = scene.regions[r];
    bool all_random = true, equal_diameters = true;
    double solid = 0.0;
    for (std::size_t s : sharing) {
      const Species& species = scene.system.species[s];
      all_random &= scene.fills[s]->arrangement == Fill::Arrangement::Random;
      equal_diameters &= species.diameter == scene.system.species[sharing.front()].diameter;
      solid += static_cast<double>(counts[s]) * species.volume();
    }
    const double bound = !equal_diameters ? 1.0
                         : all_random     ? kRandomCloseFraction
                                          : kDensestEqualFraction;
    const double phi = solid / region.volume();
    if (phi <= bound) continue;
    std::string message = scene.fills[sharing.back()]->amount_where + ": the fills of region \"" +
                          region.name + "\" (" + short_number(region.volume()) + " m^3) ask for";
    for (std::size_t k = 0; k < sharing.size(); ++k) {
      const std::size_t s = sharing[k];
      const Fill& fill = *scene.fills[s];
      message += std::string(k == 0                    ? " "
                             : k + 1 == sharing.size() ? " and "
                                                       : ", ") +
                 std::to_string(counts[s]) + " particles of species \"" +
                 scene.system.species[s].name + "\" (" + fill.amount_key + " = " +
                 fill.amount_text + " at " + fill.amount_where + ")";
    }
    message += ", together " + short_number(phi) + " of its volume; ";
    if (!equal_diameters)
      message +=
          "spheres placed in a region lie inside it without overlapping, so together they can "
          "never fill more than all of it";
    else if (all_random)
      message += "they have one diameter, and random insertion can never fill more than " +
                 format_number(kRandomCloseFraction) +
                 " of a region with equal spheres (random close packing)";
    else
      message += "they have one diameter, and no arrangement of equal spheres fills more than " +
                 short_number(kDensestEqualFraction) +
                 " of a region (the fcc packing, pi / sqrt(18))";
    throw SceneError(
        message + ". Use fewer particles, a larger region, or put the species in separate regions");
  }
}

}  // namespace carom
