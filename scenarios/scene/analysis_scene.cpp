#include "scenarios/scene/analysis_scene.hpp"

#include <cmath>

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

}  // namespace

void read_analysis(TableReader& root, Scene& scene) {
  AnalysisSettings& a = scene.analysis;
  auto section = root.table("analysis");
  if (!section) return;
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
  if (auto f = section->table("fields")) {
    a.field_cells = read_cells(*f, "cells", {1, 1, 1});
    f->finish();
  }
  section->finish();
}

}  // namespace carom
