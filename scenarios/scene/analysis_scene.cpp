#include "scenarios/scene/analysis_scene.hpp"

#include "scenarios/scene/impact_speed.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace carom {

namespace {

/// A whole number of cells per axis, at least 1.
std::array<int, 3> read_cells(TableReader& t, std::string_view key,
                              const std::array<int, 3>& fallback) {
  const Vec3 given =
      t.vector3(key, Vec3(fallback[0], fallback[1], fallback[2]),
                Range{1.0, 1e4, false, false, "sample cells per axis (whole numbers)"});
  std::array<int, 3> cells{};
  for (int k = 0; k < 3; ++k) {
    if (given[k] != std::floor(given[k])) t.fail(key, "must be whole numbers of cells per axis");
    cells[k] = static_cast<int>(given[k]);
  }
  return cells;
}

/// [analysis.profiles]: heights (required), thickness, axis, bins, start.
void read_profiles(TableReader& t, Scene& scene) {
  ProfileSettings& p = scene.analysis.profiles;
  const Domain& domain = scene.system.domain;
  const int vertical = scene.system.flight.vertical_axis();
  const std::string up(1, "xyz"[vertical]);
  if (!t.has("heights")) t.fail("heights", "is missing (section centres along " + up + ", m)");
  p.heights =
      t.numbers("heights", Range{domain.lower[vertical], domain.upper[vertical], false, false,
                                 "section centres along " + up +
                                     " (the vertical axis), m, "
                                     "inside the domain"});
  if (p.heights.empty()) t.fail("heights", "is empty (give at least one section centre, m)");
  const double extent = domain.upper[vertical] - domain.lower[vertical];
  p.thickness = t.number("thickness", extent / 20.0,
                         Range{0.0, extent, true, false, "section thickness along " + up + ", m"});
  const std::string axis = t.string("axis", vertical == 0 ? "y" : "x", {"x", "y", "z"});
  p.axis = axis[0] - 'x';
  if (p.axis == vertical)
    t.fail("axis",
           "is the vertical axis " + up + ": bins run across the sections (choose another axis)");
  p.bins = static_cast<int>(t.integer("bins", 10, 1, 10000, "bins across the domain"));
  p.start = t.number("start", 0.0, Range{0.0, INFINITY, false, true, "start of the averaging, s"});
  t.finish();
}

/// [analysis.bed]: height_shares, threshold, bin, start, probes, probe_heights, map_axis,
/// map_bins, map_centre, map_thickness (SCENES.md); every default resolved here.
void read_bed_section(TableReader& t, Scene& scene) {
  BedSettings& b = scene.analysis.bed;
  b.enabled = true;
  const Domain& domain = scene.system.domain;
  const int vertical = scene.system.flight.vertical_axis();
  const std::string up(1, "xyz"[vertical]);
  const double extent = domain.upper[vertical] - domain.lower[vertical];
  double largest = 0.0;
  for (const Species& s : scene.system.species) largest = std::max(largest, s.diameter);
  if (t.has("height_shares")) {
    b.height_shares = t.numbers(
        "height_shares", Range{0.0, 1.0, true, false, "shares of the beads below each bed height"});
    if (b.height_shares.empty())
      t.fail("height_shares", "is empty (give at least one share, e.g. [0.95, 0.99])");
  }
  b.threshold = t.number(
      "threshold", 0.1,
      Range{0.0, 1.0, true, true, "solid fraction below which the bed surface is taken"});
  b.bin = t.number("bin", largest,
                   Range{0.0, extent, true, false,
                         "bin thickness of the solid-fraction profile along " + up + ", m"});
  b.start = t.number("start", 0.0, Range{0.0, INFINITY, false, true, "start of the averaging, s"});
  const bool gas = scene.gas.coupling != CouplingLevel::None;
  for (const char* key : {"probes", "probe_heights"})
    if (t.has(key) && !gas)
      t.fail(key, "reads the gas pressure, and the scene has no [gas] (remove the key or add a gas)");
  if (t.has("probes")) {
    b.probes = t.required_vector3_list("probes", 1, Range::any("probe points, m"));
    for (std::size_t k = 0; k < b.probes.size(); ++k)
      for (int a = 0; a < 3; ++a)
        if (!(b.probes[k][a] >= domain.lower[a] && b.probes[k][a] <= domain.upper[a]))
          t.fail("probes", "has point " + std::to_string(k + 1) + " with " + std::string(1, "xyz"[a]) +
                               " = " + format_number(b.probes[k][a]) +
                               " outside the domain, allowed range [" + format_number(domain.lower[a]) +
                               ", " + format_number(domain.upper[a]) + "] (probe points, m)");
  }
  b.probe_heights = t.numbers(
      "probe_heights",
      Range{0.0, extent, false, false, "probe heights above the floor along " + up + ", m"});
  const std::string axis = t.string("map_axis", vertical == 0 ? "y" : "x", {"x", "y", "z"});
  b.map_axis = axis[0] - 'x';
  if (b.map_axis == vertical)
    t.fail("map_axis", "is the vertical axis " + up + ": the maps run across it (choose another axis)");
  const int depth = 3 - vertical - b.map_axis;
  // Default bins: about two largest diameters each, at most 50 per axis (every sample writes 32
  // bytes per bin to run.h5: 80 kB at 50 x 50).
  const auto default_bins = [&](int a) {
    const double length = domain.upper[a] - domain.lower[a];
    return largest > 0.0 ? std::clamp(static_cast<int>(std::floor(length / (2.0 * largest))), 1, 50) : 1;
  };
  b.map_bins = {default_bins(b.map_axis), default_bins(vertical)};
  if (t.has("map_bins")) {
    const std::vector<double> given =
        t.numbers("map_bins", Range{1.0, 1e4, false, false, "map bins across and up (whole numbers)"});
    if (given.size() != 2 || given[0] != std::floor(given[0]) || given[1] != std::floor(given[1]))
      t.fail("map_bins", "must be two whole numbers of bins: [across, up]");
    b.map_bins = {static_cast<int>(given[0]), static_cast<int>(given[1])};
  }
  const double deep = domain.upper[depth] - domain.lower[depth];
  const std::string third(1, "xyz"[depth]);
  b.map_centre = t.number("map_centre", 0.5 * (domain.lower[depth] + domain.upper[depth]),
                          Range{domain.lower[depth], domain.upper[depth], false, false,
                                "centre of the maps' slab along " + third + ", m"});
  b.map_thickness =
      t.number("map_thickness", largest > 0.0 ? std::min(deep, 4.0 * largest) : deep,
               Range{0.0, deep, true, false, "thickness of the maps' slab along " + third + ", m"});
  t.finish();
}

}  // namespace

void read_analysis(TableReader& root, Scene& scene) {
  AnalysisSettings& a = scene.analysis;
  scene.system.impact_speed = default_impact_speed(scene.system);
  auto section = root.table("analysis");
  if (!section) return;
  scene.system.impact_speed = section->number(
      "impact_speed", scene.system.impact_speed,
      Range{0.0, INFINITY, false, true,
            "normal approach speed above which a collision counts as an impact, m/s"});
  if (auto m = section->table("mixing")) {
    a.mixing_species = static_cast<std::int32_t>(species_index(*m, "species", scene));
    a.mixing_cells = read_cells(*m, "cells", a.mixing_cells);
    a.mixing_region = region_index(*m, "region", scene);
    a.min_particles = static_cast<std::size_t>(
        m->integer("min_particles", 5, 1, 1000000,
                   "particles of the tagged species a sample cell needs to count"));
    m->finish();
  }
  if (auto p = section->table("profiles")) read_profiles(*p, scene);
  if (auto p = section->table("plugs")) {
    PlugSettings& plugs = scene.analysis.plugs;
    plugs.enabled = true;
    const double threshold = p->number(
        "threshold", 0.3,
        Range{0.0, 1.0, true, true, "solid fraction at and above which a bin belongs to a plug"});
    std::vector<double> others = p->numbers(
        "sensitivity",
        Range{0.0, 1.0, true, true, "further thresholds reported to show the choice's effect"});
    if (!p->has("sensitivity")) others = {threshold - 0.1, threshold + 0.1};
    plugs.thresholds = {threshold};
    for (double t : others)
      if (t > 0 && t < 1 && t != threshold) plugs.thresholds.push_back(t);
    plugs.bin = p->number("bin", 0.0,
                          Range{0.0, INFINITY, false, true,
                                "bin length along the vertical axis, m (0: the largest diameter)"});
    plugs.min_bins =
        static_cast<int>(p->integer("min_bins", 2, 1, 1000, "bins the shortest plug spans"));
    plugs.rate_window =
        p->number("rate_window", 0.05,
                  Range{0.0, INFINITY, true, true, "shortest window of the bed-top speeds, s"});
    p->finish();
  }
  if (auto b = section->table("bed")) read_bed_section(*b, scene);
  if (auto f = section->table("fields")) {
    a.field_cells = read_cells(*f, "cells", {1, 1, 1});
    f->finish();
  }
  section->finish();
}

}  // namespace carom
