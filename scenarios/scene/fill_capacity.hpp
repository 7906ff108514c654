#pragma once
/// Fills that cannot fit, refused before any particle is placed.
///
/// Placing a fill allocates and tries every particle, so an impossible one (1e8 particles in a
/// box that holds a thousand) would take minutes and gigabytes before it failed. Each fill is
/// checked first against the most particles of its species its region can hold:
///   random        0.64 of the region's volume (random close packing of equal spheres, Scott
///                 and Kilgour 1969; random sequential insertion, which the placement is, jams
///                 far below it, near 0.38 (Torquato, Uche and Stillinger 2006), so a fill above
///                 0.64 can never be placed, one between 0.38 and 0.64 is tried and fails with
///                 the placement's own message);
///   fcc, cubic    the sites of the lattice the placement would lay out (placement.hpp), at
///                 contact spacing.
/// Fills of several species into the same region are then bounded together, by a fraction of
/// the region's volume that no placement can exceed: 0.64 when they are all random and of one
/// diameter (the rule above: species are only labels), 0.7405 when they have one diameter and
/// some are lattices (the densest packing of equal spheres, pi / sqrt(18)), and the whole
/// region when their diameters differ (spheres inside a region, not overlapping).
/// Listed particles and those of initial.from_file are left to the placement, so the checks
/// never refuse fills that could be placed.
#include <cstddef>
#include <vector>

#include "scenarios/scene/scene.hpp"

namespace carom {

/// The most particles of species s that its fill's region can hold by the rule above.
std::size_t fill_capacity(const Scene& scene, std::size_t s);

/// Throws SceneError for the first fill whose count (`counts`, from fill_counts) exceeds its
/// capacity, naming the file, line, key and value, and the largest count that can fit.
void check_fill_capacities(const Scene& scene, const std::vector<std::size_t>& counts);

/// Throws SceneError when the fills of several species into one region together exceed the
/// bound above, naming each fill's key, value and line; check_fill_capacities calls it last.
void check_shared_regions(const Scene& scene, const std::vector<std::size_t>& counts);

}  // namespace carom
