#pragma once
/// The collision grid of the Monte Carlo method: uniform cells over the box, and in each cell
/// and for each species the statistics of the particles there, from which a particle's
/// fictitious collision partners are drawn.
///
/// The statistics are those of the particles' states at the start of a step (no averaging over
/// steps: a cell's statistics never lag behind its particles, at the price of noise where cells
/// hold few particles). A particle asking about its own cell does not see itself: its own
/// contribution is taken out of the sums (else with 8 particles a cell, the density of its
/// partners would be 1/8 too high).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/domain.hpp"
#include "core/vec3.hpp"

namespace carom {

/// What a particle sees of the partners of one species in its cell.
struct PartnerStatistics {
  double count = 0;                     ///< Partners in the cell (the asking particle left out).
  double number_density = 0;            ///< n = count / cell volume, 1/m^3.
  double mean_radius = 0;               ///< <R0>, m.
  Vec3 mean_velocity = Vec3::Zero();    ///< <V0>, m/s.
  /// Standard deviation of each velocity component, m/s: the population value (sum of
  /// squares over count), so that a partner drawn from the Gaussians has the second moment of a
  /// particle picked at random from the cell. The "unbiased" count - 1 form adds the scatter of
  /// the cell mean once more: partners are then hotter than the particles by 1 + 1/count, and an
  /// elastic gas heats without end (measured: T x 2.7 in 35 collisions per particle with 10
  /// particles a cell).
  Vec3 velocity_std = Vec3::Zero();
  Vec3 mean_spin = Vec3::Zero();        ///< <w0>, rad/s.
};

/// One particle's contribution, to be taken out of its own cell's sums.
struct OwnContribution {
  std::uint32_t species = 0;
  double radius = 0;      ///< m.
  Vec3 velocity;          ///< m/s.
  Vec3 spin;              ///< rad/s.
};

class CollisionGrid {
 public:
  CollisionGrid() = default;
  /// Cells of edge at least `cell_size` (m) over the box of `domain`, for `species` species.
  CollisionGrid(const Domain& domain, double cell_size, std::size_t species);

  /// Empties every cell.
  void clear();
  /// Adds a particle of species s, radius a (m), velocity v, spin w at position r; returns its
  /// cell.
  std::int32_t add(const Vec3& r, std::uint32_t s, double a, const Vec3& v, const Vec3& w);

  /// The flat index of the cell holding r (positions outside the box: the nearest cell; on a
  /// periodic axis the wrapped one).
  std::int32_t cell_of(const Vec3& r) const;
  /// The partners of species s in `cell`; `own` (a particle of that cell) is left out when given.
  PartnerStatistics partners(std::int32_t cell, std::uint32_t s, const OwnContribution* own) const;
  /// Lists the particles of each cell and species, for partners drawn from a cell's particles
  /// (PartnerModel::CellParticle); call after every add(): particle i of species species[i],
  /// velocity velocity[i] (m/s), lies in cell[i].
  void list_members(const std::vector<std::int32_t>& cell,
                    const std::vector<std::uint32_t>& species, const std::vector<Vec3>& velocity);
  /// The particles (indices) of species s in `cell`, in index order, as last listed.
  std::span<const std::uint32_t> members(std::int32_t cell, std::uint32_t s) const {
    const std::size_t k = static_cast<std::size_t>(cell) * species_ + s;
    return {members_.data() + member_begin_[k], member_begin_[k + 1] - member_begin_[k]};
  }
  /// Mean velocity of every particle of species s in `cell` (none left out), m/s.
  Vec3 mean_velocity(std::int32_t cell, std::uint32_t s) const {
    const Sums& sum = sums(cell, s);
    return sum.count > 0.5 ? Vec3(sum.velocity / sum.count) : Vec3::Zero();
  }
  /// The largest |v_j - mean_velocity(cell, s)| over the listed particles, m/s.
  double largest_deviation(std::int32_t cell, std::uint32_t s) const {
    return largest_deviation_[static_cast<std::size_t>(cell) * species_ + s];
  }
  /// Solid volume fraction of `cell` (every particle counted), and xi2 = (pi/6) sum_k n_k d_k^2
  /// (1/m), for the contact value.
  double solid_fraction(std::int32_t cell) const;
  double xi2(std::int32_t cell) const;

  std::array<int, 3> cells() const { return cells_; }
  std::size_t cell_count() const { return static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2]; }
  Vec3 cell_size() const { return size_; }
  double cell_volume() const { return size_.prod(); }

 private:
  /// The sums of one species in one cell.
  struct Sums {
    double count = 0;
    double radius = 0;                 ///< sum R, m.
    double radius_squared = 0;         ///< sum R^2, m^2 (for xi2).
    double radius_cubed = 0;           ///< sum R^3, m^3 (for the solid fraction).
    Vec3 velocity = Vec3::Zero();      ///< sum v.
    Vec3 velocity_squared = Vec3::Zero();  ///< sum of v componentwise squared.
    Vec3 spin = Vec3::Zero();          ///< sum w.
  };
  const Sums& sums(std::int32_t cell, std::uint32_t s) const { return sums_[cell * species_ + s]; }

  Domain domain_;
  std::array<int, 3> cells_{1, 1, 1};
  Vec3 size_ = Vec3::Ones();
  std::size_t species_ = 0;
  std::vector<Sums> sums_;  ///< [cell * species + s].
  // list_members: the particles of [cell * species + s] are members_[member_begin_[k] ..
  // member_begin_[k + 1]); largest_deviation_[k] as largest_deviation().
  std::vector<std::size_t> member_begin_;
  std::vector<std::uint32_t> members_;
  std::vector<double> largest_deviation_;
};

}  // namespace carom
