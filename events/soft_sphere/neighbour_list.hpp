#pragma once
/// Verlet lists with a skin, built on a uniform cell grid, for the soft-sphere method.
///
/// A pair (i, j) is listed when the gap between the spheres is below the skin at the build;
/// the list stays valid until some particle has moved more than half the skin since (then two
/// particles can have closed the skin between them; the engine bounds that displacement). Polydisperse systems (fines 1:10): the
/// cells are sized by the smallest particles, and each pair is found from its larger member,
/// which searches the cells within its own diameter plus the skin. Fines thus search 27 small
/// cells, and no cell holds ~1000 fines as a grid sized by the largest particle would.
///
/// Every pair is listed once, as (owner, partner), owner the larger sphere (the lower index
/// among equals); pairs are in order of owner, then partner, so that force sums, and a list
/// rebuilt from the same positions, are the same bit for bit. Walls: each particle lists the
/// walls within the skin.
#include <cstdint>
#include <vector>

#include "core/domain.hpp"
#include "core/vec3.hpp"
#include "core/wall.hpp"

namespace carom {

/// What a listed pair remembers between steps (its contact history).
struct PairContactState {
  std::int32_t owner = 0;    ///< The larger particle (lower index among equal sizes).
  std::int32_t partner = 0;  ///< The other particle.
  bool touching = false;     ///< In contact at the last force evaluation.
  double since = 0;          ///< Time the present contact began, s.
  Vec3 spring = Vec3::Zero();  ///< Tangential spring displacement xi, m (in the tangent plane).
  double overlap = 0;          ///< Overlap at the last force evaluation, m (its k_t's).
};

/// What a listed particle-wall pair remembers.
struct WallContactState {
  std::int32_t particle = 0;  ///< The particle.
  std::int32_t wall = 0;      ///< Index into System::walls.
  bool touching = false;      ///< In contact at the last force evaluation.
  double since = 0;           ///< Time the present contact began, s.
  Vec3 spring = Vec3::Zero();  ///< Tangential spring displacement xi, m.
  double overlap = 0;          ///< Overlap at the last force evaluation, m.
};

class NeighbourList {
 public:
  /// skin: m (> 0).
  NeighbourList(const Domain& domain, double skin) : domain_(domain), skin_(skin) {}

  /// Rebuilds the lists for the particles at `position` with `radius`, and carries the contact
  /// histories of the pairs that stay listed over from the previous lists.
  void build(const std::vector<Vec3>& position, const std::vector<double>& radius,
             const std::vector<Wall>& walls);

  std::vector<PairContactState>& pairs() { return pairs_; }
  const std::vector<PairContactState>& pairs() const { return pairs_; }
  std::vector<WallContactState>& wall_pairs() { return wall_pairs_; }
  const std::vector<WallContactState>& wall_pairs() const { return wall_pairs_; }
  /// Positions at the last build, m (saved in checkpoints, so that a restored list is the same).
  const std::vector<Vec3>& reference_positions() const { return reference_; }
  /// Restores lists saved with a checkpoint.
  void restore(std::vector<Vec3> reference, std::vector<PairContactState> pairs,
               std::vector<WallContactState> wall_pairs) {
    reference_ = std::move(reference);
    pairs_ = std::move(pairs);
    wall_pairs_ = std::move(wall_pairs);
  }
  double skin() const { return skin_; }
  /// Number of builds so far.
  std::uint64_t builds() const { return builds_; }
  void set_builds(std::uint64_t builds) { builds_ = builds; }

  /// The slow oracle: every pair within the skin by an all-pairs scan (owner rule as above),
  /// for tests.
  static std::vector<PairContactState> brute_force(const Domain& domain, double skin,
                                                   const std::vector<Vec3>& position,
                                                   const std::vector<double>& radius);

 private:
  Domain domain_;
  double skin_;
  std::vector<Vec3> reference_;
  std::vector<PairContactState> pairs_;
  std::vector<WallContactState> wall_pairs_;
  std::uint64_t builds_ = 0;
  // Buffers kept from build to build, so that a build does not map fresh memory (at 1e5
  // particles the new pair list cost more in page faults than in the search).
  std::vector<PairContactState> spare_pairs_;
  /// A particle as the search reads it, copied in cell order: the cells of a row along x are
  /// one contiguous stretch of memory.
  struct CellEntry {
    Vec3 position;
    double radius;
    std::int32_t index;
  };
  std::vector<CellEntry> entries_;
};

/// True when particle j is listed under owner i: the larger, the lower index among equals.
inline bool owns(double radius_i, std::int32_t i, double radius_j, std::int32_t j) {
  return radius_j < radius_i || (radius_j == radius_i && j > i);
}

}  // namespace carom
