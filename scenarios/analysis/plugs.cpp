#include "scenarios/analysis/plugs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "scenarios/run/summary.hpp"

namespace carom {

namespace {

/// Mean and (population) standard deviation.
void mean_std(const std::vector<double>& x, double& mean, double& sd) {
  mean = sd = NAN;
  if (x.empty()) return;
  double sum = 0.0;
  for (double v : x) sum += v;
  mean = sum / static_cast<double>(x.size());
  double var = 0.0;
  for (double v : x) var += (v - mean) * (v - mean);
  sd = std::sqrt(var / static_cast<double>(x.size()));
}

/// The plug (index from the bottom) holding height z, or -1.
int plug_of(const std::vector<Plug>& plugs, double z) {
  for (std::size_t k = 0; k < plugs.size(); ++k)
    if (z >= plugs[k].lower && z < plugs[k].upper) return static_cast<int>(k);
  return -1;
}

/// The top of plug `top`: the height at which the profile, taken at the bin centres and linear
/// between them, falls through the threshold above the plug's last bin (its upper end when the
/// profile ends there).
double bed_top(const std::vector<double>& profile, const Plug& top, double bottom, double bin,
               double threshold) {
  const std::size_t last = static_cast<std::size_t>(std::lround((top.upper - bottom) / bin)) - 1;
  if (last + 1 >= profile.size()) return top.upper;
  const double above = profile[last], below = profile[last + 1];
  return bottom + (static_cast<double>(last) + 0.5) * bin +
         bin * (above - threshold) / (above - below);
}

}  // namespace

std::vector<Plug> detect_plugs(const std::vector<double>& profile, double bottom, double bin,
                               double threshold, int min_bins) {
  std::vector<Plug> plugs;
  const int n = static_cast<int>(profile.size());
  int start = -1;
  for (int b = 0; b <= n; ++b) {
    const bool dense = b < n && profile[static_cast<std::size_t>(b)] >= threshold;
    if (dense && start < 0) start = b;
    if (!dense && start >= 0) {
      if (b - start >= min_bins) plugs.push_back({bottom + start * bin, bottom + b * bin});
      start = -1;
    }
  }
  return plugs;
}

std::vector<double> axial_solid_fraction(const std::vector<double>& heights,
                                         const std::vector<double>& radii, double bottom,
                                         double bin, int bins, double area) {
  if (heights.size() != radii.size())
    throw std::invalid_argument("axial_solid_fraction: heights and radii differ in length");
  std::vector<double> profile(static_cast<std::size_t>(bins), 0.0);
  for (std::size_t i = 0; i < heights.size(); ++i) {
    const double b = std::floor((heights[i] - bottom) / bin);
    if (!(b >= 0 && b < bins)) continue;
    profile[static_cast<std::size_t>(b)] += 4.0 / 3.0 * std::numbers::pi * radii[i] * radii[i] * radii[i];
  }
  for (double& v : profile) v /= area * bin;
  return profile;
}

std::vector<PlugConclusions> conclude_plugs(const PlugGeometry& g, const std::vector<double>& times,
                                            const std::vector<double>& profiles,
                                            const std::vector<double>& heights,
                                            std::size_t particles) {
  const std::size_t rows = times.size(), B = static_cast<std::size_t>(g.bins);
  if (profiles.size() < rows * B || heights.size() < rows * particles)
    throw std::invalid_argument("conclude_plugs: fewer profile or height rows than times");
  std::vector<PlugConclusions> out;
  for (double threshold : g.thresholds) {
    PlugConclusions c;
    c.threshold = threshold;
    std::vector<std::vector<Plug>> plugs(rows);
    std::vector<double> counts, lengths, tops, tops_at(rows, NAN);
    for (std::size_t r = 0; r < rows; ++r) {
      const std::vector<double> profile(
          profiles.begin() + static_cast<std::ptrdiff_t>(r * B),
          profiles.begin() + static_cast<std::ptrdiff_t>((r + 1) * B));
      plugs[r] = detect_plugs(profile, g.bottom, g.bin, threshold, g.min_bins);
      counts.push_back(static_cast<double>(plugs[r].size()));
      for (const Plug& p : plugs[r]) lengths.push_back(p.length() / g.diameter);
      if (!plugs[r].empty()) {
        tops_at[r] = bed_top(profile, plugs[r].back(), g.bottom, g.bin, threshold);
        tops.push_back(tops_at[r]);
      }
    }
    mean_std(counts, c.plugs_mean, c.plugs_std);
    mean_std(lengths, c.length_mean, c.length_std);
    c.plug_count = lengths.size();
    double top_sum = 0.0;
    for (double t : tops) top_sum += t;
    c.bed_top_mean = tops.empty() ? NAN : top_sum / static_cast<double>(tops.size());
    // Plug changes between consecutive samples with the same plug count.
    std::vector<char> changed(particles, 0);
    for (std::size_t r = 1; r < rows; ++r) {
      const std::vector<Plug>& a = plugs[r - 1];
      const std::vector<Plug>& b = plugs[r];
      if (a.empty() || a.size() != b.size()) continue;
      for (std::size_t i = 0; i < particles; ++i) {
        const int before = plug_of(a, heights[(r - 1) * particles + i]);
        const int after = plug_of(b, heights[r * particles + i]);
        if (before >= 0 && after >= 0 && before != after) changed[i] = 1;
      }
    }
    // Bed-top speeds over successive windows of at least g.rate_window, where the number of
    // plugs is the same at both ends; the top interpolated to the threshold crossing.
    std::vector<double> rises, falls;
    for (std::size_t r = 0; r < rows;) {
      std::size_t s = r + 1;
      while (s < rows && times[s] < times[r] + g.rate_window - 1e-12) ++s;
      if (s >= rows) break;
      if (!plugs[r].empty() && plugs[r].size() == plugs[s].size()) {
        const double speed = (tops_at[s] - tops_at[r]) / (times[s] - times[r]);
        if (speed > 0) rises.push_back(speed);
        if (speed < 0) falls.push_back(speed);
      }
      r = s;
    }
    double sd = 0;
    mean_std(rises, c.rise_speed, sd);
    mean_std(falls, c.fall_speed, sd);
    if (rises.empty()) c.rise_speed = 0.0;
    if (falls.empty()) c.fall_speed = 0.0;
    std::size_t movers = 0;
    for (char x : changed) movers += x != 0;
    c.exchange = particles > 0 ? static_cast<double>(movers) / static_cast<double>(particles) : NAN;
    // Travel in 1 s: each sample t against the first sample at or after t + 1 s (within half a
    // sample interval of it).
    double travel = 0.0;
    std::size_t pairs = 0;
    for (std::size_t r = 0, s = 0; r < rows; ++r) {
      while (s < rows && times[s] < times[r] + 1.0 - 1e-9) ++s;
      if (s >= rows) break;
      const double interval = s > 0 ? times[s] - times[s - 1] : 0.0;
      if (times[s] - (times[r] + 1.0) > 0.5 * interval + 1e-9) continue;
      for (std::size_t i = 0; i < particles; ++i) {
        // A particle that left (an outflow) has no height (NaN) from then on.
        const double moved = std::abs(heights[s * particles + i] - heights[r * particles + i]);
        if (!std::isfinite(moved)) continue;
        travel += moved;
        ++pairs;
      }
    }
    c.travel = pairs > 0 ? travel / static_cast<double>(pairs) : NAN;
    out.push_back(c);
  }
  return out;
}

std::string plugs_json(const PlugGeometry& g, const std::vector<PlugConclusions>& c) {
  std::ostringstream j;
  j << "{\"bin\": " << json_number(g.bin) << ", \"bottom\": " << json_number(g.bottom)
    << ", \"area\": " << json_number(g.area) << ", \"diameter\": " << json_number(g.diameter)
    << ", \"min_bins\": " << g.min_bins << ", \"by_threshold\": [";
  for (std::size_t k = 0; k < c.size(); ++k) {
    const PlugConclusions& x = c[k];
    j << (k ? ", " : "") << "{\"threshold\": " << json_number(x.threshold)
      << ", \"plugs_mean\": " << json_number(x.plugs_mean)
      << ", \"plugs_std\": " << json_number(x.plugs_std)
      << ", \"length_mean\": " << json_number(x.length_mean)
      << ", \"length_std\": " << json_number(x.length_std)
      << ", \"plugs_counted\": " << x.plug_count
      << ", \"bed_top_mean\": " << json_number(x.bed_top_mean)
      << ", \"rise_speed\": " << json_number(x.rise_speed)
      << ", \"fall_speed\": " << json_number(x.fall_speed)
      << ", \"exchange\": " << json_number(x.exchange)
      << ", \"travel_1s\": " << json_number(x.travel) << "}";
  }
  j << "]}";
  return j.str();
}

std::string plugs_report(const PlugGeometry& g, const std::vector<PlugConclusions>& c) {
  std::ostringstream r;
  r.precision(3);
  r << "\n## Plugs\n\nA plug is a run of at least " << g.min_bins << " bins of " << g.bin * 1e3
    << " mm whose solid fraction is at or above the threshold; lengths in largest diameters d = "
    << g.diameter * 1e3 << " mm. The first row is the scene's threshold; the others show how "
    << "much the choice matters.\n\n"
    << "| threshold | plugs per sample | lambda/d mean | lambda/d std | bed top (mm) | rise (m/s) "
       "| fall (m/s) | particles changing plugs | travel in 1 s (mm) |\n"
       "|---|---|---|---|---|---|---|---|---|\n";
  for (const PlugConclusions& x : c)
    r << "| " << x.threshold << " | " << x.plugs_mean << " ± " << x.plugs_std << " | "
      << x.length_mean << " | " << x.length_std << " | " << x.bed_top_mean * 1e3 << " | "
      << x.rise_speed << " | " << x.fall_speed << " | " << x.exchange << " | " << x.travel * 1e3
      << " |\n";
  return r.str();
}

}  // namespace carom
