#include "scenarios/analysis/gas_probes.hpp"

#include <algorithm>
#include <cmath>

namespace carom {

namespace {

/// The two cell-centre indices about coordinate c (in cells from the lower face) along an axis
/// of n cells, and the weight of the upper one; clamped to the outermost centres.
struct CentrePair {
  int lower = 0, upper = 0;
  double weight = 0;
};
CentrePair centre_pair(double c, int n) {
  const double x = std::clamp(c - 0.5, 0.0, static_cast<double>(n - 1));
  CentrePair p;
  p.lower = std::min(static_cast<int>(std::floor(x)), n - 1);
  p.upper = std::min(p.lower + 1, n - 1);
  p.weight = x - p.lower;
  return p;
}

}  // namespace

double pressure_at_point(const std::vector<double>& pressure, const std::array<int, 3>& cells,
                         const Vec3& lower, const Vec3& size, const Vec3& r) {
  std::array<CentrePair, 3> p;
  for (int k = 0; k < 3; ++k) p[k] = centre_pair((r[k] - lower[k]) / size[k], cells[k]);
  double value = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    double weight = 1.0;
    std::array<int, 3> index{};
    for (int k = 0; k < 3; ++k) {
      const bool up = (corner >> k) & 1;
      index[k] = up ? p[k].upper : p[k].lower;
      weight *= up ? p[k].weight : 1.0 - p[k].weight;
    }
    if (weight == 0.0) continue;
    value += weight * pressure[static_cast<std::size_t>(index[0] + cells[0] * (index[1] + cells[1] * index[2]))];
  }
  return value;
}

double pressure_at_level(const std::vector<double>& pressure, const std::vector<double>& open_volume,
                         const std::array<int, 3>& cells, const Vec3& lower, const Vec3& size,
                         int axis, double level) {
  // Open-volume-weighted mean of every layer of cells across `axis`.
  std::vector<double> sum(static_cast<std::size_t>(cells[axis]), 0.0), weight(sum.size(), 0.0);
  for (int z = 0; z < cells[2]; ++z)
    for (int y = 0; y < cells[1]; ++y)
      for (int x = 0; x < cells[0]; ++x) {
        const std::size_t c = static_cast<std::size_t>(x + cells[0] * (y + cells[1] * z));
        const std::size_t layer = static_cast<std::size_t>(std::array<int, 3>{x, y, z}[axis]);
        sum[layer] += open_volume[c] * pressure[c];
        weight[layer] += open_volume[c];
      }
  const CentrePair p = centre_pair((level - lower[axis]) / size[axis], cells[axis]);
  const double a = sum[p.lower] / weight[p.lower], b = sum[p.upper] / weight[p.upper];
  return p.weight == 0.0 ? a : (1.0 - p.weight) * a + p.weight * b;
}

}  // namespace carom
