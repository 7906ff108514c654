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
  if (auto f = section->table("fields")) {
    a.field_cells = read_cells(*f, "cells", {1, 1, 1});
    f->finish();
  }
  section->finish();
}

}  // namespace carom
