#pragma once
/// Putting particles into a box without overlaps: random sequential insertion and lattices.
///
/// A Placer knows, in advance, the radius of every particle the System will hold (so it can
/// build the hierarchical grid once) and the particles already placed. Each new sphere is
/// accepted only where it overlaps no placed sphere and no wall, and lies in its region:
/// wholly inside on walled axes, centre inside on a periodic axis the region spans entirely.
///
/// Particles read from a previous run (initial.from_file) are in initial_file.hpp, the settling
/// run (initial.settle_time) in settling.hpp.
#include <csignal>
#include <cstdint>
#include <string>
#include <vector>

#include "core/cell_grid.hpp"
#include "core/rng.hpp"
#include "core/system.hpp"

namespace carom {

class Placer {
 public:
  /// `radii`: the radius of every particle the system will hold, in the order they will be added
  /// (the system's current particles first). Throws std::invalid_argument if the grid cannot be
  /// built (a periodic axis shorter than three diameters).
  Placer(System& system, std::vector<double> radii);

  /// A signal handler's flag (may be null): while it is raised, random() and lattice() stop
  /// placing and return what they placed so far (a long placement answers a signal at once).
  void set_stop_flag(const volatile std::sig_atomic_t* stop) { stop_ = stop; }
  /// True when the stop flag is raised.
  bool stopped() const { return stop_ != nullptr && *stop_ != 0; }

  /// Adds one particle of species s at r (velocity zero) if it fits; returns whether it did.
  bool try_place(std::uint32_t s, const Vec3& r);

  /// Random sequential insertion of `count` particles of species s with centres uniform in the
  /// allowed part of [lower, upper]. Gives up after `attempts_per_particle` failed tries in a row
  /// for one particle, or when the stop flag is raised; returns how many were placed.
  std::size_t random(std::uint32_t s, std::size_t count, const Vec3& lower, const Vec3& upper, Rng& rng,
                     std::size_t attempts_per_particle = 20000);

  /// `count` particles on a face-centred cubic (fcc = true) or simple cubic lattice spread over
  /// [lower, upper] as evenly as the count allows; sites that would overlap placed particles or
  /// walls are skipped. With gravity, the lowest sites (along g) fill first. Returns how many
  /// were placed (fewer than count when the region holds fewer sites at contact spacing, or when
  /// the stop flag is raised).
  std::size_t lattice(std::uint32_t s, std::size_t count, const Vec3& lower, const Vec3& upper, bool fcc);

  /// The centre range [lo, hi] on axis k for a sphere of radius a in [lower, upper]; `wraps` is set
  /// when the axis is periodic and the region spans it, so that centres run over [lower, upper).
  void centre_range(int k, double a, const Vec3& lower, const Vec3& upper, double& lo, double& hi, bool& wraps) const;

 private:
  bool fits(std::int32_t index, const Vec3& r, double a) const;

  System& system_;
  std::vector<double> radii_;
  HierarchicalGrid grid_;
  const volatile std::sig_atomic_t* stop_ = nullptr;
};

/// The centre range [lo, hi] on axis k for a sphere of radius a in [lower, upper] of `domain`;
/// `wraps` is set when the axis is periodic and the region spans it, so that centres run over
/// [lower, upper).
void centre_range(const Domain& domain, int k, double a, const Vec3& lower, const Vec3& upper, double& lo,
                  double& hi, bool& wraps);

/// The lattice a fill of `count` spheres of radius a in [lower, upper] uses: the spacing h (m) of
/// the cubic grid of candidate sites (fcc keeps those with an even index sum) and how many sites
/// it has there (before any is skipped for overlapping placed particles or walls). h starts at
/// the spacing that spreads `count` over the region and shrinks until the region holds `count`
/// sites, but never below contact: `sites` < count then means the lattice cannot hold them.
struct LatticePlan {
  double spacing = 0;     ///< h, m.
  std::size_t sites = 0;  ///< Sites at that spacing.
};
LatticePlan plan_lattice(const Domain& domain, double a, std::size_t count, const Vec3& lower, const Vec3& upper,
                         bool fcc);

/// Maxwellian velocities for particles [first, end): component standard deviation sqrt(T / m_i)
/// (equipartition at temperature T, J), or v_rms / sqrt(3) for every particle when v_rms > 0.
/// Their total momentum is then removed and their kinetic energy scaled to the exact target:
/// (3/2)(n - 1) T, or (1/2) sum m_i v_rms^2 (n - 1)/n.
void set_maxwellian(System& system, std::size_t first, double temperature, double rms_velocity, Rng& rng);

}  // namespace carom
