#include "scenarios/analysis/bed_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/nan.hpp"
#include "scenarios/analysis/gas_probes.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

namespace {

/// Volume of a sphere of radius a below the plane at s (m) from its centre, m^3: a cap of
/// height a + s, pi (a + s)^2 (2a - s) / 3, clamped to 0 and the whole sphere.
double sphere_volume_below(double a, double s) {
  s = std::clamp(s, -a, a);
  return std::numbers::pi * (a + s) * (a + s) * (2.0 * a - s) / 3.0;
}

/// Mean, standard deviation, minimum and maximum of the finite values of column k of rows
/// [first, rows) of a series `width` wide.
SeriesSpread column_spread(const std::vector<double>& series, std::size_t width, std::size_t k,
                           std::size_t first, std::size_t rows) {
  SeriesSpread s{kNaN, kNaN, kNaN, kNaN};
  std::vector<double> x;
  for (std::size_t r = first; r < rows; ++r)
    if (const double v = series[r * width + k]; std::isfinite(v)) x.push_back(v);
  if (x.empty()) return s;
  double sum = 0.0;
  for (double v : x) sum += v;
  s.mean = sum / static_cast<double>(x.size());
  double square = 0.0;
  for (double v : x) square += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(square / static_cast<double>(x.size()));
  s.min = *std::min_element(x.begin(), x.end());
  s.max = *std::max_element(x.begin(), x.end());
  return s;
}

/// Column k's evenly spaced finite values from row `first` on (see the header), and their
/// interval (s).
std::vector<double> even_run(const std::vector<double>& times, const std::vector<double>& series,
                             std::size_t width, std::size_t k, std::size_t first,
                             double& interval) {
  std::size_t r = first;
  while (r < times.size() && !std::isfinite(series[r * width + k])) ++r;
  std::vector<double> values;
  if (r >= times.size()) return values;
  const std::size_t begin = r;
  values.push_back(series[r * width + k]);
  const double step = r + 1 < times.size() ? times[r + 1] - times[r] : 0.0;
  for (++r; r < times.size(); ++r) {
    const double v = series[r * width + k];
    if (!std::isfinite(v) || std::abs(times[r] - times[r - 1] - step) > 1e-6 * step) break;
    values.push_back(v);
  }
  interval = values.size() > 1 ? (times[begin + values.size() - 1] - times[begin]) /
                                     static_cast<double>(values.size() - 1)
                               : 0.0;
  return values;
}

}  // namespace

BedGeometry bed_geometry(const Scene& scene) {
  const System& system = scene.system;
  const BedSettings& s = scene.analysis.bed;
  BedGeometry g;
  g.vertical = system.flight.vertical_axis();
  const Vec3 length = system.domain.length();
  g.floor = system.domain.lower[g.vertical];
  g.extent = length[g.vertical];
  g.area = length.prod() / length[g.vertical];
  for (const Wall& w : system.walls)
    if (const auto* c = std::get_if<CylinderWall>(&w.shape); c != nullptr && g.vertical == 2)
      g.area = std::min(g.area, std::numbers::pi * c->radius * c->radius);
  g.shares = s.height_shares;
  g.threshold = s.threshold;
  g.bin = s.bin;
  g.bins = std::max(1, static_cast<int>(std::floor(g.extent / g.bin)));
  g.start = s.start;
  g.gas = scene.gas.coupling != CouplingLevel::None;
  g.gas_density = scene.gas.density;
  g.gravity = system.flight.gravity.norm();
  g.gas_height = g.extent;
  g.probes = s.probes;
  g.probe_heights = s.probe_heights;
  g.map_axis = s.map_axis;
  g.map_bins = s.map_bins;
  g.map_lower = system.domain.lower[g.map_axis];
  g.map_upper = system.domain.upper[g.map_axis];
  g.slab_centre = s.map_centre;
  g.slab_thickness = s.map_thickness;
  for (int k = 0; k < 3; ++k) {
    g.lower[k] = system.domain.lower[k];
    g.upper[k] = system.domain.upper[k];
    g.periodic[k] = system.domain.periodic[k];
  }
  return g;
}

std::vector<double> share_heights(std::vector<double> tops, const std::vector<double>& shares) {
  std::vector<double> out;
  const std::size_t n = tops.size();
  for (double q : shares) {
    if (n == 0) {
      out.push_back(kNaN);
      continue;
    }
    const double wanted = std::ceil(q * static_cast<double>(n) * (1.0 - 1e-12));
    const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(wanted), 1, n);
    std::nth_element(tops.begin(), tops.begin() + static_cast<std::ptrdiff_t>(k - 1), tops.end());
    out.push_back(tops[k - 1]);
  }
  return out;
}

std::vector<double> layer_solid_fraction(const std::vector<double>& heights,
                                         const std::vector<double>& radii, double bin, int bins,
                                         double area) {
  if (heights.size() != radii.size())
    throw std::invalid_argument("layer_solid_fraction: heights and radii differ in length");
  std::vector<double> profile(static_cast<std::size_t>(bins), 0.0);
  for (std::size_t i = 0; i < heights.size(); ++i) {
    const double z = heights[i], a = radii[i];
    const int low = std::max(0, static_cast<int>(std::floor((z - a) / bin)));
    const int high = std::min(bins - 1, static_cast<int>(std::floor((z + a) / bin)));
    for (int b = low; b <= high; ++b)
      profile[static_cast<std::size_t>(b)] +=
          sphere_volume_below(a, (b + 1) * bin - z) - sphere_volume_below(a, b * bin - z);
  }
  for (double& v : profile) v /= area * bin;
  return profile;
}

double surface_height(const std::vector<double>& profile, double bin, double threshold) {
  for (std::size_t j = profile.size(); j-- > 0;) {
    if (!(profile[j] >= threshold)) continue;
    if (j + 1 == profile.size()) return static_cast<double>(profile.size()) * bin;
    const double above = profile[j], beyond = profile[j + 1];
    return (static_cast<double>(j) + 0.5) * bin + bin * (above - threshold) / (above - beyond);
  }
  return kNaN;
}

BedSample sample_bed(const BedGeometry& g, const CollisionMethod& sim, const GasCoupling* gas) {
  const System& system = sim.system();
  const ParticleStore& p = system.particles;
  const std::size_t n = sim.particle_count();
  std::vector<Vec3> position(n), velocity(n);
  std::vector<double> centre(n), top(n);
  for (std::size_t i = 0; i < n; ++i) {
    position[i] = sim.position(i);
    velocity[i] = sim.velocity(i);
    centre[i] = position[i][g.vertical] - g.floor;
    top[i] = centre[i] + p.radius[i];
  }
  BedSample s;
  s.heights = share_heights(top, g.shares);
  s.heights.push_back(
      surface_height(layer_solid_fraction(centre, p.radius, g.bin, g.bins, g.area), g.bin, g.threshold));
  if (g.gas) {
    s.pressure.assign(3, kNaN);
    s.probes.assign(g.probe_width(), kNaN);
    if (gas != nullptr) {
      double open = 0.0, weight = 0.0;
      for (double v : gas->open_volume()) open += v;
      for (std::size_t i = 0; i < n; ++i)
        weight += (system.species[p.species[i]].density - g.gas_density) * g.gravity * 4.0 / 3.0 *
                  std::numbers::pi * p.radius[i] * p.radius[i] * p.radius[i];
      s.pressure[2] = weight / (open / g.gas_height);
    }
    if (gas != nullptr && gas->times().steps > 0) {
      s.pressure[0] = gas->pressure_drop();
      s.pressure[1] = gas->momentum_inflow();
      const std::vector<double>& field = gas->pressure_field();
      std::size_t k = 0;
      for (const Vec3& r : g.probes)
        s.probes[k++] = pressure_at_point(field, gas->cells(), gas->grid_lower(), gas->cell_size(), r);
      for (double h : g.probe_heights)
        s.probes[k++] = pressure_at_level(field, gas->open_volume(), gas->cells(), gas->grid_lower(),
                                          gas->cell_size(), g.vertical, g.floor + h);
    }
  }
  s.map = map_sums(g, position, velocity, p.radius, p.mass);
  return s;
}

BedConclusions conclude_bed(const BedGeometry& g, const std::vector<double>& times,
                            const std::vector<double>& heights, const std::vector<double>& pressure,
                            const std::vector<double>& probes, const std::vector<double>& map) {
  const std::size_t rows = times.size();
  const std::size_t H = g.height_width(), P = g.probe_width(), M = g.map_width();
  if (heights.size() < rows * H || map.size() < rows * M ||
      (!pressure.empty() && pressure.size() < rows * 3) ||
      (!probes.empty() && probes.size() < rows * P))
    throw std::invalid_argument("conclude_bed: fewer rows in a series than times");
  BedConclusions c;
  std::size_t first = 0;
  while (first < rows && times[first] < g.start) ++first;
  c.samples = rows - first;
  c.first = c.samples > 0 ? times[first] : kNaN;
  c.last = c.samples > 0 ? times.back() : kNaN;
  c.interval = c.samples > 1 ? (c.last - c.first) / static_cast<double>(c.samples - 1) : kNaN;
  for (std::size_t k = 0; k < H; ++k) c.heights.push_back(column_spread(heights, H, k, first, rows));
  if (!pressure.empty()) {
    c.pressure = true;
    c.pressure_drop = column_spread(pressure, 3, 0, first, rows);
    c.momentum_inflow = column_spread(pressure, 3, 1, first, rows).mean;
    c.buoyant_weight = column_spread(pressure, 3, 2, first, rows).mean;
    c.gas_column = g.gas_density * g.gravity * g.gas_height;
    c.bed_pressure_drop = c.pressure_drop.mean - c.gas_column + c.momentum_inflow;
  }
  if (!probes.empty())
    for (std::size_t k = 0; k < P; ++k) {
      double interval = 0.0;
      const std::vector<double> values = even_run(times, probes, P, k, first, interval);
      c.probes.push_back(amplitude_spectrum(values, interval));
    }
  // The maps: sums over the samples, then per bin volume and per mass.
  const std::size_t bins = M / BedGeometry::kMapValues;
  std::vector<double> total(M, 0.0);
  for (std::size_t r = first; r < rows; ++r)
    for (std::size_t k = 0; k < M; ++k) total[k] += map[r * M + k];
  const double volume = static_cast<double>(c.samples) * g.map_bin_volume();
  c.solid_fraction.assign(bins, kNaN);
  c.velocity.assign(2 * bins, kNaN);
  c.flux.assign(2 * bins, kNaN);
  if (c.samples == 0) return c;
  for (std::size_t b = 0; b < bins; ++b) {
    const double* sum = &total[b * BedGeometry::kMapValues];
    c.solid_fraction[b] = sum[0] / volume;
    for (std::size_t k = 0; k < 2; ++k) {
      c.flux[2 * b + k] = sum[2 + k] / volume;
      if (sum[1] > 0.0) c.velocity[2 * b + k] = sum[2 + k] / sum[1];
    }
  }
  return c;
}

}  // namespace carom
