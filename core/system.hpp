#pragma once
/// Everything that defines a granular system before it runs: box, walls, species, laws, particles.
#include <string>
#include <vector>

#include "ballistic_flight.hpp"
#include "domain.hpp"
#include "materials.hpp"
#include "particles.hpp"
#include "species.hpp"
#include "wall.hpp"

namespace carom {

struct System {
  Domain domain;                 ///< The box and its periodic axes.
  std::vector<Species> species;  ///< Particle kinds; particles refer to them by index.
  std::vector<Wall> walls;       ///< Fixed boundaries (box walls, inclined planes, a cylinder).
  MaterialTable materials;       ///< Contact laws per species pair and species-wall pair.
  BallisticFlight flight;        ///< Gravity and the trajectory between events.
  ParticleStore particles;       ///< The particles.
  /// Species that enter through inflows during the run (none of them may be present at the
  /// start): the methods size their steps and grids for them as for particles present.
  std::vector<std::uint32_t> entering_species;
  /// Largest speed at which particles enter through inflows, m/s.
  double entering_speed = 0;
  /// A collision is an impact when its normal approach speed exceeds this, m/s (0: every
  /// collision is one). The scene's [analysis] impact_speed; its default and the reasoning behind
  /// it: scenarios/scene/impact_speed.hpp.
  double impact_speed = 0;

  /// Whether a collision at normal approach speed `approach` (m/s, > 0 when approaching) is an
  /// impact.
  bool is_impact(double approach) const { return approach > impact_speed; }

  /// Adds one particle of species s with velocity v and spin w at position r (time 0).
  void add_particle(std::uint32_t s, const Vec3& r, const Vec3& v, const Vec3& w = Vec3::Zero()) {
    const Species& kind = species.at(s);
    particles.add(r, v, w, kind.radius(), kind.mass(), kind.inertia(), s, particles.size());
  }
};

/// The six planes of the box on every non-periodic axis, named x_low, x_high, y_low, ...
std::vector<Wall> box_walls(const Domain& domain);

/// Relative round-off the engine tolerates in contacts: a pair may overlap by up to this fraction
/// of its contact distance, a particle poke through a wall by this fraction of its radius (the
/// invariant checks of a run use the same bound). States taken from a run (a settled bed, a
/// snapshot read back) can overlap by ~1e-16 relative, because positions at a common time are
/// computed from different event times.
inline constexpr double kContactTolerance = 1e-10;

/// Throws std::invalid_argument (naming the particles) when two particles overlap, a particle
/// pokes through a wall or lies outside the box, or any state is not finite. O(N) with a grid.
/// `overlap_tolerance`: relative overlap accepted (see kContactTolerance); 0 is strict, as used
/// for freshly placed and listed particles. The default is what the engine accepts mid-run, and
/// is what the event-driven engine checks at its start.
void validate_initial_state(const System& system, double overlap_tolerance = kContactTolerance);

}  // namespace carom
