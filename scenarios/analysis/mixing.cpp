#include "scenarios/analysis/mixing.hpp"

#include "core/nan.hpp"
#include "scenarios/analysis/log_least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace carom {

namespace {

void require_same_length(std::size_t a, std::size_t b, const char* what) {
  if (a != b)
    throw std::invalid_argument(std::string(what) + ": the inputs differ in length (" +
                                std::to_string(a) + " vs " + std::to_string(b) + ")");
}

void require_axis(int axis, const char* what) {
  if (axis < 0 || axis > 2)
    throw std::invalid_argument(std::string(what) + ": the vertical axis must be 0, 1 or 2, not " +
                                std::to_string(axis));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Lacey index

LaceyIndex lacey_index(const std::vector<Vec3>& positions, const std::vector<char>& tagged,
                       const SampleGrid& grid, std::size_t min_particles_per_cell) {
  require_same_length(positions.size(), tagged.size(), "lacey_index");
  grid.check();
  std::vector<std::size_t> count(grid.size(), 0), tagged_count(grid.size(), 0);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const int cell = grid.cell_of(positions[i]);
    if (cell < 0) continue;
    ++count[cell];
    if (tagged[i] != 0) ++tagged_count[cell];
  }

  std::size_t particles = 0, tagged_total = 0, cells_used = 0;
  for (std::size_t c = 0; c < count.size(); ++c) {
    if (count[c] == 0 || count[c] < min_particles_per_cell) continue;
    particles += count[c];
    tagged_total += tagged_count[c];
    ++cells_used;
  }

  LaceyIndex result{kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, cells_used};
  if (particles == 0) return result;
  const double P = double(tagged_total) / double(particles);
  result.tagged_fraction = P;
  result.segregated_variance = P * (1.0 - P);

  double weighted_square_deviation = 0.0;  // sum_k N_k (x_k - P)^2
  for (std::size_t c = 0; c < count.size(); ++c) {
    if (count[c] == 0 || count[c] < min_particles_per_cell) continue;
    const double deviation = double(tagged_count[c]) / double(count[c]) - P;
    weighted_square_deviation += double(count[c]) * deviation * deviation;
  }
  result.variance = weighted_square_deviation / double(particles);
  if (cells_used < 2) return result;

  result.particles_per_cell = double(particles - 1) / double(cells_used - 1);
  result.random_variance = result.segregated_variance / result.particles_per_cell;
  if (tagged_total == 0 || tagged_total == particles) return result;
  result.index = (result.segregated_variance - result.variance) /
                 (result.segregated_variance - result.random_variance);
  return result;
}

// ---------------------------------------------------------------------------------------------
// Mixing rate

namespace {

/// The points of a mixing curve that a fit uses, in time order, and the start M0 of the model
/// M(t) = 1 - (1 - M0) exp(-k t).
struct MixingCurve {
  std::vector<double> time, lacey;
  double unmixed_start = 1.0;  ///< 1 - M0.

  /// exp(-k t), with exp(-k 0) = 1 also for k = +inf.
  static double decay(double rate, double time) {
    return time == 0.0 ? 1.0 : std::exp(-rate * time);
  }

  /// Sum of squared residuals of 1 - (1 - M0) exp(-k t).
  double squared_residuals(double rate) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      const double residual = lacey[i] - 1.0 + unmixed_start * decay(rate, time[i]);
      sum += residual * residual;
    }
    return sum;
  }
  /// sum_i r_i t_i exp(-k t_i) = -dF/dk / (2 (1 - M0)): positive where F falls with k.
  double normal_equation(double rate) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < time.size(); ++i) {
      const double unmixed = decay(rate, time[i]);
      sum += (lacey[i] - 1.0 + unmixed_start * unmixed) * time[i] * unmixed;
    }
    return sum;
  }
};

/// First time the curve reaches `level`, interpolating linearly between samples; NaN if never.
double first_crossing(const MixingCurve& curve, double level) {
  for (std::size_t i = 0; i < curve.time.size(); ++i) {
    if (curve.lacey[i] < level) continue;
    if (i == 0) return curve.time[0];
    const double fraction = (level - curve.lacey[i - 1]) / (curve.lacey[i] - curve.lacey[i - 1]);
    return curve.time[i - 1] + fraction * (curve.time[i] - curve.time[i - 1]);
  }
  return kNaN;
}

}  // namespace

MixingRate fit_mixing_rate(const std::vector<double>& times, const std::vector<double>& lacey, double start) {
  require_same_length(times.size(), lacey.size(), "fit_mixing_rate");
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < times.size(); ++i)
    if (std::isfinite(times[i]) && times[i] >= 0.0 && std::isfinite(lacey[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return times[i] < times[j]; });
  MixingCurve curve;
  curve.unmixed_start = 1.0 - start;
  for (std::size_t i : order) {
    curve.time.push_back(times[i]);
    curve.lacey.push_back(lacey[i]);
  }

  MixingRate result{kNaN, kNaN, first_crossing(curve, 0.8), kNaN, curve.time.size(), false, start};
  const auto first_positive =
      std::find_if(curve.time.begin(), curve.time.end(), [](double t) { return t > 0.0; });
  if (curve.time.size() < 3 || first_positive == curve.time.end() || !(start < 0.8)) return result;

  // k over the range the data can resolve.
  const LogFit fit = minimize_on_log_range(curve, std::log(1e-4 / curve.time.back()),
                                           std::log(1e3 / *first_positive));
  result.rate = fit.value;
  result.valid = fit.valid;
  result.time_to_08_fit = std::log((1.0 - start) / 0.2) / result.rate;
  result.rms_residual = std::sqrt(curve.squared_residuals(result.rate) / double(curve.time.size()));
  return result;
}

// ---------------------------------------------------------------------------------------------
// Segregation indices

double segregation_index(const std::vector<Vec3>& positions,
                         const std::vector<std::uint32_t>& species, std::uint32_t a,
                         std::uint32_t b, double floor_height, int vertical_axis) {
  require_same_length(positions.size(), species.size(), "segregation_index");
  require_axis(vertical_axis, "segregation_index");
  double height_a = 0.0, height_b = 0.0;
  std::size_t count_a = 0, count_b = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double height = positions[i][vertical_axis] - floor_height;
    if (species[i] == a) height_a += height, ++count_a;
    if (species[i] == b) height_b += height, ++count_b;
  }
  if (count_a == 0 || count_b == 0) return kNaN;
  const double mean_a = height_a / double(count_a), mean_b = height_b / double(count_b);
  if (mean_a + mean_b == 0.0) return kNaN;
  return 2.0 * (mean_a - mean_b) / (mean_a + mean_b);
}

double rowe_nienow_index(const std::vector<Vec3>& positions,
                         const std::vector<std::uint32_t>& species,
                         const std::vector<double>& radii, std::uint32_t jetsam,
                         std::uint32_t flotsam, double split_height, int vertical_axis) {
  require_same_length(positions.size(), species.size(), "rowe_nienow_index");
  require_same_length(positions.size(), radii.size(), "rowe_nienow_index");
  require_axis(vertical_axis, "rowe_nienow_index");
  double jetsam_volume = 0.0, solids_volume = 0.0;              // whole bed (r^3 units)
  double jetsam_volume_upper = 0.0, solids_volume_upper = 0.0;  // above split_height
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (species[i] != jetsam && species[i] != flotsam) continue;
    const double volume = radii[i] * radii[i] * radii[i];  // the 4 pi/3 cancels in the fractions
    const bool is_jetsam = species[i] == jetsam;
    const bool upper = positions[i][vertical_axis] > split_height;
    solids_volume += volume;
    if (is_jetsam) jetsam_volume += volume;
    if (upper) solids_volume_upper += volume;
    if (upper && is_jetsam) jetsam_volume_upper += volume;
  }
  if (jetsam_volume == 0.0 || solids_volume_upper == 0.0) return kNaN;
  return (jetsam_volume_upper / solids_volume_upper) / (jetsam_volume / solids_volume);
}

}  // namespace carom
