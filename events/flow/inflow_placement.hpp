#pragma once
/// Placing entering particles at random without overlap (an inflow's step): a bucket grid of
/// the particles near the slab, so that one try costs a few cells, not a sweep over all N.
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "core/system.hpp"
#include "events/flow/flow_definitions.hpp"

namespace carom {

/// The spheres near one inflow's slab at one flow step, in uniform cells, and the free places
/// among them. A place is free when the new sphere's gap to every sphere is >= 0
/// (|r - r_j| >= a + a_j, the periodic images included), to every wall (Wall::gap >= 0) and to
/// the box's faces on walled axes.
class SlabPlacer {
 public:
  /// Centres of new spheres of radius `radius` (m) go in `centres` (inside the domain); spheres
  /// of radius up to `max_radius` (m) will be added as obstacles.
  SlabPlacer(const Box& centres, double radius, double max_radius, const Domain& domain,
             const std::vector<Wall>& walls);

  /// Adds the sphere at r (m; folded into the box on periodic axes) of radius a (m), with each
  /// of its periodic images that could touch a new sphere; spheres too far away are skipped.
  void add(const Vec3& r, double a);
  /// True when a new sphere centred at r is free of every sphere added, every wall and the box.
  bool free(const Vec3& r) const;
  /// A free centre uniform in `centres`, trying up to `attempts` times (each try draws the x, y
  /// and z coordinates in that order); the sphere found is added. False when none was found.
  bool place(Rng& rng, int attempts, Vec3& found);
  /// Tries made by place() that found the spot taken.
  std::uint64_t failed_tries() const { return failed_tries_; }

 private:
  /// Flat index of the cell holding r (clamped into the grid).
  std::size_t cell_of(const Vec3& r) const;

  Box centres_;    ///< Where new centres go, m.
  double radius_;  ///< New spheres' radius, m.
  double reach_;   ///< radius + the largest obstacle radius: the contact distance, m.
  const Domain& domain_;
  const std::vector<Wall>& walls_;
  Box grid_;                           ///< centres grown by reach: the cells' extent, m.
  Vec3 cell_size_ = Vec3::Ones();      ///< m (>= reach: a query spans at most 3 cells per axis).
  int cells_[3] = {1, 1, 1};           ///< Cells per axis.
  std::vector<std::int32_t> head_;     ///< First sphere of each cell, -1 when empty.
  std::vector<std::int32_t> next_;     ///< Next sphere in the same cell, -1 at the end.
  std::vector<Vec3> position_;         ///< Centre of each sphere (or image) added, m.
  std::vector<double> sphere_radius_;  ///< Its radius, m.
  std::uint64_t failed_tries_ = 0;
};

}  // namespace carom
