#pragma once
/// The simulation box: an axis-aligned box, each axis periodic or bounded by walls.
#include <array>
#include <cmath>

#include "vec3.hpp"

namespace carom {

struct Domain {
  Vec3 lower = Vec3::Zero();                ///< Lower corner, m.
  Vec3 upper = Vec3::Ones();                ///< Upper corner, m.
  std::array<bool, 3> periodic{false, false, false};  ///< Periodic axes (x, y, z).

  /// Edge lengths, m.
  Vec3 length() const { return upper - lower; }
  double volume() const { return length().prod(); }

  /// Maps a separation vector to its nearest periodic image (unchanged on walled axes).
  /// Valid for separations shorter than 1.5 box lengths. Stored particle states never lie
  /// outside their grid cell (a crossing brings the state up to date), so this holds.
  void minimum_image(Vec3& separation) const {
    for (int k = 0; k < 3; ++k) {
      if (!periodic[k]) continue;
      const double length_k = upper[k] - lower[k];
      if (separation[k] > 0.5 * length_k)
        separation[k] -= length_k;
      else if (separation[k] < -0.5 * length_k)
        separation[k] += length_k;
    }
  }
};

}  // namespace carom
