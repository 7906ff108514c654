#include "scenarios/analysis/section_profiles.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "scenarios/run/summary.hpp"

namespace carom {

namespace {

/// Offsets of the values of one bin in a row of sums.
enum Value : std::size_t { kCount = 0, kSolid = 1, kVelocity = 2, kSquare = 5, kSpin = 8 };

}  // namespace

std::vector<double> profile_sums(const ProfileGeometry& g, const std::vector<Vec3>& positions,
                                 const std::vector<Vec3>& velocities,
                                 const std::vector<Vec3>& spins, const std::vector<double>& radii) {
  const std::size_t n = positions.size();
  if (velocities.size() != n || spins.size() != n || radii.size() != n)
    throw std::invalid_argument(
        "profile_sums: positions, velocities, spins and radii differ in length");
  std::vector<double> row(g.row_width(), 0.0);
  const std::size_t B = static_cast<std::size_t>(g.bins);
  const double width = (g.upper - g.lower) / g.bins;
  for (std::size_t i = 0; i < n; ++i) {
    const double across = positions[i][g.axis];
    if (!(across >= g.lower && across < g.upper)) continue;
    const std::size_t b =
        std::min(B - 1, static_cast<std::size_t>(std::floor((across - g.lower) / width)));
    for (std::size_t k = 0; k < g.heights.size(); ++k) {
      const double offset = positions[i][g.vertical] - g.heights[k];
      if (!(offset >= -0.5 * g.thickness && offset < 0.5 * g.thickness)) continue;
      double* bin = row.data() + (k * B + b) * ProfileGeometry::kValuesPerBin;
      bin[kCount] += 1.0;
      bin[kSolid] += 4.0 / 3.0 * std::numbers::pi * radii[i] * radii[i] * radii[i];
      for (int c = 0; c < 3; ++c) {
        bin[kVelocity + c] += velocities[i][c];
        bin[kSquare + c] += velocities[i][c] * velocities[i][c];
        bin[kSpin + c] += spins[i][c];
      }
    }
  }
  return row;
}

ProfileConclusions conclude_profiles(const ProfileGeometry& g, const std::vector<double>& times,
                                     const std::vector<double>& sums) {
  const std::size_t width = g.row_width(), B = static_cast<std::size_t>(g.bins);
  if (sums.size() < times.size() * width)
    throw std::invalid_argument("conclude_profiles: fewer sums than rows of times");
  std::vector<double> total(width, 0.0);
  ProfileConclusions c;
  for (std::size_t r = 0; r < times.size(); ++r) {
    if (times[r] < g.start) continue;
    if (c.samples == 0) c.first = times[r];
    c.last = times[r];
    ++c.samples;
    for (std::size_t j = 0; j < width; ++j) total[j] += sums[r * width + j];
  }
  for (std::size_t k = 0; k < g.heights.size(); ++k) {
    SectionProfile s;
    s.height = g.heights[k];
    for (std::size_t b = 0; b < B; ++b) {
      const double* bin = total.data() + (k * B + b) * ProfileGeometry::kValuesPerBin;
      const double count = bin[kCount];
      const double samples = static_cast<double>(c.samples);
      s.solid_fraction.push_back(c.samples > 0 ? bin[kSolid] / (samples * g.bin_volume()) : NAN);
      s.particles.push_back(c.samples > 0 ? count / samples : NAN);
      Vec3 mean, spread, spin;
      for (int d = 0; d < 3; ++d) {
        if (count == 0.0) {
          mean[d] = spread[d] = spin[d] = NAN;
          continue;
        }
        mean[d] = bin[kVelocity + d] / count;
        // Population spread of the particle samples; round-off can take the difference of two
        // nearly equal numbers below zero when every sample has the same velocity.
        spread[d] = std::sqrt(std::max(0.0, bin[kSquare + d] / count - mean[d] * mean[d]));
        spin[d] = bin[kSpin + d] / count;
      }
      s.mean_velocity.push_back(mean);
      s.std_velocity.push_back(spread);
      s.mean_spin.push_back(spin);
    }
    c.sections.push_back(std::move(s));
  }
  return c;
}

std::string profiles_json(const ProfileGeometry& g, const ProfileConclusions& c) {
  std::ostringstream j;
  const auto list = [](const std::vector<double>& values) {
    std::string out = "[";
    for (std::size_t k = 0; k < values.size(); ++k) out += (k ? ", " : "") + json_number(values[k]);
    return out + "]";
  };
  const auto vectors = [](const std::vector<Vec3>& values) {
    std::string out = "[";
    for (std::size_t k = 0; k < values.size(); ++k)
      out += (k ? ", [" : "[") + json_number(values[k].x()) + ", " + json_number(values[k].y()) +
             ", " + json_number(values[k].z()) + "]";
    return out + "]";
  };
  std::vector<double> centres;
  for (int b = 0; b < g.bins; ++b) centres.push_back(g.bin_centre(b));
  j << "{\"axis\": \""
    << "xyz"[g.axis] << "\", \"vertical\": \""
    << "xyz"[g.vertical] << "\", \"thickness\": " << json_number(g.thickness)
    << ", \"start\": " << json_number(g.start) << ", \"samples\": " << c.samples
    << ", \"first\": " << json_number(c.first) << ", \"last\": " << json_number(c.last)
    << ", \"bin_centres\": " << list(centres) << ", \"sections\": [";
  for (std::size_t k = 0; k < c.sections.size(); ++k) {
    const SectionProfile& s = c.sections[k];
    j << (k ? ", " : "") << "{\"height\": " << json_number(s.height)
      << ", \"solid_fraction\": " << list(s.solid_fraction)
      << ", \"particles_per_sample\": " << list(s.particles)
      << ", \"mean_velocity\": " << vectors(s.mean_velocity)
      << ", \"std_velocity\": " << vectors(s.std_velocity)
      << ", \"mean_spin\": " << vectors(s.mean_spin) << "}";
  }
  j << "]}";
  return j.str();
}

std::string profiles_report(const ProfileGeometry& g, const ProfileConclusions& c) {
  std::ostringstream r;
  r.precision(3);
  const char across = "xyz"[g.axis], up = "xyz"[g.vertical];
  r << "\n## Profiles across sections\n\n"
    << "Bins along " << across << " in slabs " << g.thickness * 1e3 << " mm thick, averaged over "
    << c.samples << " samples";
  if (c.samples > 0) r << " from t = " << c.first << " s to " << c.last << " s";
  r << " (solid fraction of the bin's box volume; mean and standard deviation of the particles' "
       "velocities, m/s).\n";
  for (const SectionProfile& s : c.sections) {
    r << "\n"
      << up << " = " << s.height << " m:\n\n"
      << "| " << across << " (m) | solid fraction | particles | <v_" << across << "> | std v_"
      << across << " | <v_" << up << "> | std v_" << up << " |\n|---|---|---|---|---|---|---|\n";
    for (int b = 0; b < g.bins; ++b) {
      const std::size_t i = static_cast<std::size_t>(b);
      r << "| " << g.bin_centre(b) << " | " << s.solid_fraction[i] << " | " << s.particles[i]
        << " | " << s.mean_velocity[i][g.axis] << " | " << s.std_velocity[i][g.axis] << " | "
        << s.mean_velocity[i][g.vertical] << " | " << s.std_velocity[i][g.vertical] << " |\n";
    }
  }
  return r.str();
}

}  // namespace carom
