// The bed measures' outputs: run.h5 /analysis/bed (geometry, then results), summary.json's
// "bed" object and report.md's bed section (bed_measures.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/hdf5.hpp"
#include "core/nan.hpp"
#include "scenarios/analysis/bed_measures.hpp"
#include "scenarios/run/summary.hpp"

namespace carom {

namespace {

std::string bed_axis_name(int axis) { return std::string(1, "xyz"[axis]); }

/// A number for report.md: 4 significant digits, "n/a" for NaN.
std::string bed_text(double x, double scale = 1.0) {
  if (!std::isfinite(x)) return "n/a";
  std::ostringstream out;
  out.precision(4);
  out << x * scale;
  return out.str();
}

/// A dataset with its unit as the attribute "unit".
void write_with_unit(const h5::Group& group, const std::string& name,
                     const std::vector<double>& values, const std::string& unit,
                     std::vector<hsize_t> shape = {}) {
  group.write(name, values, std::move(shape)).set_attribute("unit", unit);
}

/// A scalar attribute and its unit beside it ("<name>_unit").
void attribute_with_unit(const h5::Group& group, const std::string& name, double value,
                         const std::string& unit) {
  group.set_attribute(name, value);
  group.set_attribute(name + "_unit", unit);
}

/// The probe's name in words: "point (x, y, z) mm" or "height h mm".
std::string probe_label(const BedGeometry& g, std::size_t k) {
  std::ostringstream out;
  if (k < g.probes.size()) {
    const Vec3& r = g.probes[k];
    out << "point (" << bed_text(r.x(), 1e3) << ", " << bed_text(r.y(), 1e3) << ", "
        << bed_text(r.z(), 1e3) << ") mm";
  } else {
    out << "cross-section at " << bed_text(g.probe_heights[k - g.probes.size()], 1e3) << " mm";
  }
  return out.str();
}

}  // namespace

void write_bed_setup(const h5::Group& analysis, const BedGeometry& g) {
  const h5::Group bed = analysis.create_group("bed");
  bed.set_attribute("vertical_axis", static_cast<std::int64_t>(g.vertical));
  attribute_with_unit(bed, "floor", g.floor, "m");
  attribute_with_unit(bed, "extent", g.extent, "m");
  attribute_with_unit(bed, "area", g.area, "m^2");
  attribute_with_unit(bed, "threshold", g.threshold, "1");
  attribute_with_unit(bed, "bin", g.bin, "m");
  bed.set_attribute("bins", static_cast<std::int64_t>(g.bins));
  attribute_with_unit(bed, "start", g.start, "s");
  write_with_unit(bed, "height_shares", g.shares, "1");
  if (g.gas) {
    attribute_with_unit(bed, "gas_density", g.gas_density, "kg/m^3");
    attribute_with_unit(bed, "gravity", g.gravity, "m/s^2");
    attribute_with_unit(bed, "gas_height", g.gas_height, "m");
    std::vector<double> points;
    for (const Vec3& r : g.probes) points.insert(points.end(), {r.x(), r.y(), r.z()});
    write_with_unit(bed, "probes", points, "m", {g.probes.size(), 3});
    write_with_unit(bed, "probe_heights", g.probe_heights, "m");
  }
  bed.set_attribute("map_axis", static_cast<std::int64_t>(g.map_axis));
  bed.set_attribute("map_bins", std::vector<std::int64_t>{g.map_bins[0], g.map_bins[1]});
  attribute_with_unit(bed, "map_lower", g.map_lower, "m");
  attribute_with_unit(bed, "map_upper", g.map_upper, "m");
  attribute_with_unit(bed, "slab_centre", g.slab_centre, "m");
  attribute_with_unit(bed, "slab_thickness", g.slab_thickness, "m");
  // The units of the series this observable adds to /timeseries.
  bed.set_attribute("bed_height_unit", std::string("m"));
  bed.set_attribute("bed_pressure_unit", std::string("Pa"));
  bed.set_attribute("bed_probe_pressure_unit", std::string("Pa"));
  bed.set_attribute("bed_map_sums_unit", std::string("m^3, kg, kg m/s, kg m/s"));
}

void write_bed_results(const h5::Group& analysis, const BedGeometry& g, const BedConclusions& c) {
  const h5::Group bed = analysis.open_group("bed");
  if (bed.contains("results")) bed.remove("results");
  const h5::Group r = bed.create_group("results");
  r.set_attribute("samples", static_cast<std::int64_t>(c.samples));
  attribute_with_unit(r, "first", c.first, "s");
  attribute_with_unit(r, "last", c.last, "s");
  attribute_with_unit(r, "interval", c.interval, "s");
  std::vector<double> mean, sd, low, high;
  for (const SeriesSpread& s : c.heights) {
    mean.push_back(s.mean);
    sd.push_back(s.sd);
    low.push_back(s.min);
    high.push_back(s.max);
  }
  // One entry per share, then the solid-fraction surface.
  write_with_unit(r, "height_mean", mean, "m");
  write_with_unit(r, "height_std", sd, "m");
  write_with_unit(r, "height_min", low, "m");
  write_with_unit(r, "height_max", high, "m");
  if (c.pressure) {
    write_with_unit(r, "pressure_drop_mean", {c.pressure_drop.mean}, "Pa");
    write_with_unit(r, "pressure_drop_std", {c.pressure_drop.sd}, "Pa");
    write_with_unit(r, "gas_column", {c.gas_column}, "Pa");
    write_with_unit(r, "momentum_inflow_mean", {c.momentum_inflow}, "Pa");
    write_with_unit(r, "bed_pressure_drop", {c.bed_pressure_drop}, "Pa");
    write_with_unit(r, "buoyant_weight_per_area", {c.buoyant_weight}, "Pa");
  }
  if (!c.probes.empty()) {
    std::vector<double> pm, ps, f, a, interval;
    std::size_t width = 0;
    for (const Spectrum& s : c.probes) width = std::max(width, s.amplitude.size());
    std::vector<double> frequency(width, kNaN), amplitude(c.probes.size() * width, kNaN);
    for (std::size_t k = 0; k < c.probes.size(); ++k) {
      const Spectrum& s = c.probes[k];
      pm.push_back(s.mean);
      ps.push_back(s.standard_deviation);
      f.push_back(s.dominant_frequency);
      a.push_back(s.dominant_amplitude);
      interval.push_back(s.interval);
      for (std::size_t j = 0; j < s.amplitude.size(); ++j) {
        amplitude[k * width + j] = s.amplitude[j];
        if (s.amplitude.size() == width) frequency[j] = s.frequency[j];
      }
    }
    write_with_unit(r, "probe_mean", pm, "Pa");
    write_with_unit(r, "probe_std", ps, "Pa");
    write_with_unit(r, "probe_dominant_frequency", f, "Hz");
    write_with_unit(r, "probe_dominant_amplitude", a, "Pa");
    write_with_unit(r, "probe_interval", interval, "s");
    write_with_unit(r, "spectrum_frequency", frequency, "Hz");
    write_with_unit(r, "spectrum_amplitude", amplitude, "Pa", {c.probes.size(), width});
  }
  const hsize_t up = static_cast<hsize_t>(g.map_bins[1]), across = static_cast<hsize_t>(g.map_bins[0]);
  write_with_unit(r, "map_solid_fraction", c.solid_fraction, "1", {up, across});
  write_with_unit(r, "map_velocity", c.velocity, "m/s", {up, across, 2});
  write_with_unit(r, "map_flux", c.flux, "kg/m^2/s", {up, across, 2});
}

std::string bed_json(const BedGeometry& g, const BedConclusions& c) {
  std::ostringstream j;
  j << "{\"start\": " << json_number(g.start) << ", \"samples\": " << c.samples
    << ", \"first\": " << json_number(c.first) << ", \"last\": " << json_number(c.last)
    << ", \"interval\": " << json_number(c.interval) << ", \"vertical\": "
    << json_string(bed_axis_name(g.vertical)) << ", \"floor\": " << json_number(g.floor)
    << ", \"bin\": " << json_number(g.bin) << ", \"threshold\": " << json_number(g.threshold)
    << ", \"heights\": [";
  for (std::size_t k = 0; k < c.heights.size(); ++k) {
    const SeriesSpread& s = c.heights[k];
    j << (k ? ", " : "") << "{";
    if (k < g.shares.size())
      j << "\"definition\": \"share\", \"share\": " << json_number(g.shares[k]);
    else
      j << "\"definition\": \"solid_fraction\", \"threshold\": " << json_number(g.threshold);
    j << ", \"mean\": " << json_number(s.mean) << ", \"std\": " << json_number(s.sd)
      << ", \"min\": " << json_number(s.min) << ", \"max\": " << json_number(s.max) << "}";
  }
  j << "]";
  if (c.pressure)
    j << ", \"pressure\": {\"drop_mean\": " << json_number(c.pressure_drop.mean)
      << ", \"drop_std\": " << json_number(c.pressure_drop.sd)
      << ", \"gas_column\": " << json_number(c.gas_column)
      << ", \"momentum_inflow\": " << json_number(c.momentum_inflow)
      << ", \"bed_drop\": " << json_number(c.bed_pressure_drop)
      << ", \"buoyant_weight_per_area\": " << json_number(c.buoyant_weight)
      << ", \"bed_drop_over_weight\": " << json_number(c.bed_pressure_drop / c.buoyant_weight) << "}";
  if (!c.probes.empty()) {
    j << ", \"probes\": [";
    for (std::size_t k = 0; k < c.probes.size(); ++k) {
      const Spectrum& s = c.probes[k];
      j << (k ? ", " : "") << "{";
      if (k < g.probes.size())
        j << "\"point\": [" << json_number(g.probes[k].x()) << ", " << json_number(g.probes[k].y())
          << ", " << json_number(g.probes[k].z()) << "]";
      else
        j << "\"height\": " << json_number(g.probe_heights[k - g.probes.size()]);
      j << ", \"mean\": " << json_number(s.mean) << ", \"std\": " << json_number(s.standard_deviation)
        << ", \"dominant_frequency\": " << json_number(s.dominant_frequency)
        << ", \"dominant_amplitude\": " << json_number(s.dominant_amplitude)
        << ", \"samples\": " << s.samples << ", \"resolution\": " << json_number(s.resolution())
        << ", \"nyquist\": " << json_number(s.nyquist()) << "}";
    }
    j << "]";
  }
  // The map in numbers: the strongest upward and downward solids flux (the circulation).
  double rise = kNaN, fall = kNaN;
  for (std::size_t b = 0; 2 * b + 1 < c.flux.size(); ++b) {
    const double up = c.flux[2 * b + 1];
    if (!std::isfinite(up)) continue;
    if (!(up <= rise)) rise = up;
    if (!(up >= fall)) fall = up;
  }
  j << ", \"map\": {\"axis\": " << json_string(bed_axis_name(g.map_axis)) << ", \"bins\": ["
    << g.map_bins[0] << ", " << g.map_bins[1] << "], \"slab_centre\": " << json_number(g.slab_centre)
    << ", \"slab_thickness\": " << json_number(g.slab_thickness)
    << ", \"largest_upward_flux\": " << json_number(rise)
    << ", \"largest_downward_flux\": " << json_number(fall) << "}}";
  return j.str();
}

std::string bed_report(const BedGeometry& g, const BedConclusions& c) {
  std::ostringstream r;
  r << "\n## Bed\n\nOver " << c.samples << " samples from t = " << bed_text(c.first) << " to "
    << bed_text(c.last) << " s (every " << bed_text(c.interval) << " s; `start` = "
    << bed_text(g.start) << " s). Heights above the floor (" << bed_axis_name(g.vertical) << " = "
    << bed_text(g.floor) << " m). A share height is the height below which that share of the "
       "beads' tops lie; the surface is where the horizontally averaged solid fraction (bins of "
    << bed_text(g.bin, 1e3) << " mm, each bead's exact volume per bin) falls below "
    << bed_text(g.threshold) << ".\n";
  if (c.samples == 0) {
    r << "\nNo sample at or after `start`: the run ended before it, and there is nothing to "
         "conclude (run on, or lower `start`).\n";
    return r.str();
  }
  r << "\n| bed height | mean (mm) | std (mm) | min (mm) | max (mm) |\n"
       "|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < c.heights.size(); ++k) {
    const SeriesSpread& s = c.heights[k];
    r << "| " << (k < g.shares.size() ? bed_text(g.shares[k] * 100.0) + " % of the beads below"
                                      : "solid fraction below " + bed_text(g.threshold))
      << " | " << bed_text(s.mean, 1e3) << " | " << bed_text(s.sd, 1e3) << " | "
      << bed_text(s.min, 1e3) << " | " << bed_text(s.max, 1e3) << " |\n";
  }
  if (!c.pressure) {
    r << "\nNo gas in this scene: the pressure drop against the bed's weight and the gas pressure "
         "at probes are not measured.\n";
  } else {
    r << "\n| pressure (Pa) | value |\n|---|---|\n"
      << "| pressure drop over the domain, mean ± std | " << bed_text(c.pressure_drop.mean)
      << " ± " << bed_text(c.pressure_drop.sd) << " |\n"
      << "| gas column's own weight rho_g g H | " << bed_text(c.gas_column) << " |\n"
      << "| gas momentum inflow, mean | " << bed_text(c.momentum_inflow) << " |\n"
      << "| the part that carries the bed: drop - rho_g g H + inflow | "
      << bed_text(c.bed_pressure_drop) << " |\n"
      << "| buoyant weight per area W/A = sum (rho_p - rho_g) g V / A | "
      << bed_text(c.buoyant_weight) << " |\n"
      << "| ratio | " << bed_text(c.bed_pressure_drop / c.buoyant_weight) << " |\n";
    if (!c.probes.empty()) {
      r << "\nGas pressure at the probes: spectrum of the de-meaned, evenly spaced samples "
           "(resolution 1/T, up to the Nyquist frequency 1/(2 dt)).\n\n"
           "| probe | mean (Pa) | std (Pa) | dominant frequency (Hz) | its amplitude (Pa) | "
           "resolution (Hz) | Nyquist (Hz) |\n|---|---|---|---|---|---|---|\n";
      for (std::size_t k = 0; k < c.probes.size(); ++k) {
        const Spectrum& s = c.probes[k];
        r << "| " << probe_label(g, k) << " | " << bed_text(s.mean) << " | "
          << bed_text(s.standard_deviation) << " | " << bed_text(s.dominant_frequency) << " | "
          << bed_text(s.dominant_amplitude) << " | " << bed_text(s.resolution()) << " | "
          << bed_text(s.nyquist()) << " |\n";
      }
    }
  }
  r << "\nTime-averaged maps (solid fraction, solids velocity and mass flux) over "
    << g.map_bins[0] << " x " << g.map_bins[1] << " bins (" << bed_axis_name(g.map_axis)
    << " x " << bed_axis_name(g.vertical) << ") in the slab " << bed_text(g.slab_thickness, 1e3)
    << " mm thick about " << bed_axis_name(g.depth_axis()) << " = "
    << bed_text(g.slab_centre, 1e3) << " mm: run.h5 /analysis/bed/results.\n";
  return r.str();
}

}  // namespace carom
