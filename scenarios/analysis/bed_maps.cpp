// The bed's mid-plane map sums (bed_measures.hpp, bed_map_sums): each bead's volume, mass and
// momentum shared over the bins of the slab by the exact part of its volume in each.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fluid/overlap.hpp"
#include "scenarios/analysis/bed_measures.hpp"

namespace carom {

std::vector<double> map_sums(const BedGeometry& g, const std::vector<Vec3>& positions,
                             const std::vector<Vec3>& velocities, const std::vector<double>& radii,
                             const std::vector<double>& masses) {
  std::vector<double> row(g.map_width(), 0.0);
  const int across = g.map_axis, depth = g.depth_axis(), up = g.vertical;
  const int columns = g.map_bins[0], rows = g.map_bins[1];
  const double width = (g.map_upper - g.map_lower) / columns, height = g.extent / rows;
  const double slab_low = g.slab_centre - 0.5 * g.slab_thickness;
  const double slab_high = slab_low + g.slab_thickness;
  // The shifts to a bead's periodic images along an axis that it reaches across.
  const auto images = [&](int axis, double x, double a) {
    std::vector<double> shifts{0.0};
    if (!g.periodic[axis]) return shifts;
    const double length = g.upper[axis] - g.lower[axis];
    if (x - a < g.lower[axis]) shifts.push_back(length);
    if (x + a > g.upper[axis]) shifts.push_back(-length);
    return shifts;
  };
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double a = radii[i], sphere = 4.0 / 3.0 * std::numbers::pi * a * a * a;
    for (double shift_across : images(across, positions[i][across], a))
      for (double shift_depth : images(depth, positions[i][depth], a)) {
        Vec3 c = positions[i];
        c[across] += shift_across;
        c[depth] += shift_depth;
        if (c[depth] + a <= slab_low || c[depth] - a >= slab_high) continue;
        const int c0 = std::max(0, static_cast<int>(std::floor((c[across] - a - g.map_lower) / width)));
        const int c1 = std::min(columns - 1, static_cast<int>(std::floor((c[across] + a - g.map_lower) / width)));
        const int u0 = std::max(0, static_cast<int>(std::floor((c[up] - a - g.floor) / height)));
        const int u1 = std::min(rows - 1, static_cast<int>(std::floor((c[up] + a - g.floor) / height)));
        for (int u = u0; u <= u1; ++u)
          for (int b = c0; b <= c1; ++b) {
            Vec3 low, high;
            low[across] = g.map_lower + b * width;
            high[across] = g.map_lower + (b + 1) * width;
            low[up] = g.floor + u * height;
            high[up] = g.floor + (u + 1) * height;
            low[depth] = slab_low;
            high[depth] = slab_high;
            const double volume = sphere_box_volume(c, a, low, high);
            if (!(volume > 0.0)) continue;
            const double share = masses[i] * volume / sphere;
            double* bin = &row[(static_cast<std::size_t>(u) * static_cast<std::size_t>(columns) +
                                static_cast<std::size_t>(b)) * BedGeometry::kMapValues];
            bin[0] += volume;
            bin[1] += share;
            bin[2] += share * velocities[i][across];
            bin[3] += share * velocities[i][up];
          }
      }
  }
  return row;
}

}  // namespace carom
