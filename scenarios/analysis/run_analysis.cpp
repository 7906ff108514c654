#include "scenarios/analysis/run_analysis.hpp"

#include <algorithm>
#include <limits>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "core/hdf5.hpp"
#include "scenarios/analysis/dispersion.hpp"
#include "scenarios/analysis/local_fields.hpp"

namespace carom {

namespace {

/// Field cells of about four largest diameters across (at least one per axis).
std::array<int, 3> default_field_cells(const System& system) {
  double largest = 0.0;
  for (const Species& s : system.species) largest = std::max(largest, s.diameter);
  std::array<int, 3> cells{1, 1, 1};
  const Vec3 extent = system.domain.upper - system.domain.lower;
  for (int k = 0; k < 3; ++k)
    if (largest > 0.0)
      cells[k] = std::max(1, static_cast<int>(std::floor(extent[k] / (4.0 * largest))));
  return cells;
}

/// Row of particle `id` in the by-id arrays (ids sorted ascending): the particles of t = 0;
/// kNotAtStart for one that entered later (an inflow).
constexpr std::size_t kNotAtStart = std::numeric_limits<std::size_t>::max();
std::size_t rank_of(const std::vector<std::uint64_t>& ids, std::uint64_t id) {
  const auto it = std::lower_bound(ids.begin(), ids.end(), id);
  return it != ids.end() && *it == id ? static_cast<std::size_t>(it - ids.begin()) : kNotAtStart;
}

/// Trapezoidal time average of column k of a series with `width` values per row.
double time_average(const std::vector<double>& times, const std::vector<double>& series,
                    std::size_t width, std::size_t k) {
  const std::size_t rows = times.size();
  if (rows == 0) return NAN;
  if (rows == 1) return series[k];
  double integral = 0.0, span = 0.0;
  for (std::size_t r = 1; r < rows; ++r) {
    const double a = series[(r - 1) * width + k], b = series[r * width + k];
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    const double dt = times[r] - times[r - 1];
    integral += 0.5 * (a + b) * dt;
    span += dt;
  }
  return span > 0.0 ? integral / span : NAN;
}

/// The analysis series a run file may hold, with their widths for S species (tagged bodies'
/// series apart).
std::vector<std::pair<std::string, std::size_t>> series_widths(std::size_t species) {
  return {{"lacey_index", 1},
          {"axial_msd", 1},
          {"segregation_index", 1},
          {"granular_temperature", species},
          {"kinetic_collision_rate", species * species},
          {"kinetic_impact_rate", species * species},
          {"gas_velocity_seen", 3 * species},
          {"gas_force_mean", 3 * species},
          {"porosity_seen", species}};
}

}  // namespace

std::vector<std::pair<std::string, std::size_t>> RunAnalysis::widths() const {
  auto all = series_widths(scene_.system.species.size());
  for (auto& w : tagged_series_widths(tagged_ids_.size(), tagged_partners_)) all.push_back(w);
  if (!profiles_.heights.empty()) all.emplace_back("profile_sums", profiles_.row_width());
  if (plugs_.bins > 0) {
    all.emplace_back("axial_solid_fraction", static_cast<std::size_t>(plugs_.bins));
    all.emplace_back("plug_height", ids_.size());
  }
  if (bed_enabled_) {
    all.emplace_back("bed_height", bed_.height_width());
    if (bed_.gas) all.emplace_back("bed_pressure", 3);
    if (bed_.gas && bed_.probe_width() > 0) all.emplace_back("bed_probe_pressure", bed_.probe_width());
    all.emplace_back("bed_map_sums", bed_.map_width());
  }
  return all;
}

RunAnalysis::RunAnalysis(const Scene& scene, const CollisionMethod& sim) : scene_(scene) {
  const System& system = sim.system();
  tagged_ids_ = sim.statistics().tagged.ids;
  tagged_partners_ = sim.statistics().tagged.partners();
  const ParticleStore& p = system.particles;
  const std::size_t n = sim.particle_count();
  vertical_ = system.flight.vertical_axis();
  floor_ = system.domain.lower[vertical_];
  const AnalysisSettings& a = scene.analysis;
  const Region& region = scene.regions[a.mixing_region];
  mixing_grid_ = SampleGrid{region.lower, region.upper, a.mixing_cells};
  const bool default_fields = a.field_cells == std::array<int, 3>{0, 0, 0};
  field_grid_ = SampleGrid{system.domain.lower, system.domain.upper,
                           default_fields ? default_field_cells(system) : a.field_cells};
  if (!a.profiles.heights.empty()) {
    const ProfileSettings& s = a.profiles;
    const int third = 3 - vertical_ - s.axis;
    profiles_ = ProfileGeometry{s.heights,
                                s.thickness,
                                vertical_,
                                s.axis,
                                s.bins,
                                system.domain.lower[s.axis],
                                system.domain.upper[s.axis],
                                system.domain.upper[third] - system.domain.lower[third],
                                s.start};
  }
  if (a.bed.enabled) {
    bed_enabled_ = true;
    bed_ = bed_geometry(scene);
  }
  if (a.plugs.enabled) {
    double largest = 0.0;
    for (const Species& s : system.species) largest = std::max(largest, s.diameter);
    const Vec3 length = system.domain.length();
    plugs_.bottom = system.domain.lower[vertical_];
    plugs_.bin = a.plugs.bin > 0 ? a.plugs.bin : largest;
    plugs_.bins = std::max(1, static_cast<int>(std::floor(length[vertical_] / plugs_.bin)));
    plugs_.area = length.prod() / length[vertical_];
    for (const Wall& w : system.walls)
      if (const auto* c = std::get_if<CylinderWall>(&w.shape); c != nullptr && vertical_ == 2)
        plugs_.area = std::min(plugs_.area, std::numbers::pi * c->radius * c->radius);
    plugs_.diameter = largest;
    plugs_.min_bins = a.plugs.min_bins;
    plugs_.thresholds = a.plugs.thresholds;
    plugs_.rate_window = a.plugs.rate_window;
  }
  if (system.species.size() >= 2) {
    small_ = large_ = 0;
    for (std::size_t s = 1; s < system.species.size(); ++s) {
      if (system.species[s].diameter < system.species[small_].diameter)
        small_ = static_cast<std::int32_t>(s);
      if (system.species[s].diameter > system.species[large_].diameter)
        large_ = static_cast<std::int32_t>(s);
    }
    if (system.species[small_].diameter == system.species[large_].diameter) small_ = large_ = -1;
  }

  ids_.assign(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(n));
  std::sort(ids_.begin(), ids_.end());
  start_height_.assign(n, 0.0);
  tagged_.assign(n, 0);
  std::vector<std::size_t> mixing;  // ranks of the mixing species' particles
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = rank_of(ids_, p.id[i]);
    start_height_[r] = sim.position(i)[vertical_];
    if (static_cast<std::int32_t>(p.species[i]) == a.mixing_species) mixing.push_back(r);
  }
  // The lower half by height (ties by id) is tagged.
  std::sort(mixing.begin(), mixing.end(), [&](std::size_t x, std::size_t y) {
    return start_height_[x] != start_height_[y] ? start_height_[x] < start_height_[y] : x < y;
  });
  for (std::size_t k = 0; k < mixing.size() / 2; ++k) tagged_[mixing[k]] = 1;
}

RunAnalysis::RunAnalysis(const Scene& scene, const CollisionMethod& sim, const std::string& run_file,
                         double resume_time)
    : RunAnalysis(scene, sim) {
  // The constructor above derived grids and species from the scene; tags and start heights are
  // those of t = 0, read back (the particles have moved since).
  const h5::File file = h5::File::open(run_file, false);
  if (!file.contains("analysis"))
    throw std::runtime_error(run_file + ": no /analysis group (written by an older carom?)");
  const h5::Group group = file.open_group("analysis");
  // The particles of t = 0 (with inflow and outflow, not those of the checkpoint).
  const std::size_t n = group.open_dataset("id").size();
  ids_ = group.read<std::uint64_t>("id", {n});
  if (!std::is_sorted(ids_.begin(), ids_.end()))
    throw std::runtime_error(run_file + ": /analysis/id is not in ascending order: the file is damaged");
  const auto tags = group.read<std::int8_t>("tagged", {n});
  tagged_.assign(tags.begin(), tags.end());
  start_height_ = group.read<double>("start_height", {n});

  const h5::Group series = file.open_group("timeseries");
  const std::vector<double> times = series.read<double>("time");
  std::size_t keep = 0;
  while (keep < times.size() && times[keep] <= resume_time) ++keep;
  times_.assign(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(keep));
  for (const auto& [name, width] : widths()) {
    if (!series.contains(name)) continue;
    std::vector<double> values = series.read<double>(name);
    values.resize(std::min(values.size(), keep * width));
    history_[name] = std::move(values);
  }
}

void RunAnalysis::write_setup(const std::string& run_file) const {
  const h5::File file = h5::File::open(run_file, true);
  const h5::Group group = file.create_group("analysis");
  group.write("id", ids_);
  group.write("tagged", std::vector<std::int8_t>(tagged_.begin(), tagged_.end()));
  group.write("start_height", start_height_);
  group.set_attribute("vertical_axis", static_cast<std::int64_t>(vertical_));
  group.set_attribute("mixing_species", static_cast<std::int64_t>(scene_.analysis.mixing_species));
  auto grid = [&](const char* name, const SampleGrid& g) {
    const h5::Group sub = group.create_group(name);
    sub.write<double>("lower", {g.lower.x(), g.lower.y(), g.lower.z()});
    sub.write<double>("upper", {g.upper.x(), g.upper.y(), g.upper.z()});
    sub.write<std::int32_t>("cells", {g.cells[0], g.cells[1], g.cells[2]});
  };
  grid("mixing_grid", mixing_grid_);
  grid("field_grid", field_grid_);
  if (!tagged_ids_.empty()) {
    // The tagged bodies and the names of their partner categories (species, then walls).
    group.write("tagged_body_id", tagged_ids_);
    std::vector<std::string> partners;
    for (const Species& s : scene_.system.species) partners.push_back(s.name);
    for (const Wall& w : scene_.system.walls) partners.push_back(w.name);
    group.write_strings("tagged_partner", partners);
  }
  if (!profiles_.heights.empty()) {
    const h5::Group sub = group.create_group("profiles");
    sub.write("heights", profiles_.heights);
    sub.set_attribute("thickness", profiles_.thickness);
    sub.set_attribute("vertical_axis", static_cast<std::int64_t>(profiles_.vertical));
    sub.set_attribute("bin_axis", static_cast<std::int64_t>(profiles_.axis));
    sub.set_attribute("bins", static_cast<std::int64_t>(profiles_.bins));
    sub.set_attribute("lower", profiles_.lower);
    sub.set_attribute("upper", profiles_.upper);
    sub.set_attribute("depth", profiles_.depth);
    sub.set_attribute("start", profiles_.start);
  }
  if (plugs_.bins > 0) {
    const h5::Group sub = group.create_group("plugs");
    sub.write("thresholds", plugs_.thresholds);
    sub.set_attribute("bottom", plugs_.bottom);
    sub.set_attribute("bin", plugs_.bin);
    sub.set_attribute("bins", static_cast<std::int64_t>(plugs_.bins));
    sub.set_attribute("area", plugs_.area);
    sub.set_attribute("diameter", plugs_.diameter);
    sub.set_attribute("min_bins", static_cast<std::int64_t>(plugs_.min_bins));
  }
  if (bed_enabled_) write_bed_setup(group, bed_);
  file.flush();
}

void RunAnalysis::write_results(const std::string& run_file, const CollisionMethod& sim) const {
  if (!bed_enabled_) return;
  const Conclusions c = conclude(sim);
  const h5::File file = h5::File::open(run_file, true);
  write_bed_results(file.open_group("analysis"), bed_, c.bed);
  file.flush();
}

SeriesRow RunAnalysis::sample(const CollisionMethod& sim, const GasCoupling* gas) {
  const System& system = sim.system();
  const ParticleStore& p = system.particles;
  const std::size_t n = sim.particle_count(), S = system.species.size();
  const double t = sim.time();
  // A resumed run writes again what an older checkpoint's run had written: forget those rows.
  while (!times_.empty() && times_.back() >= t) {
    times_.pop_back();
    for (const auto& [name, width] : widths()) {
      auto found = history_.find(name);
      if (found != history_.end() && found->second.size() >= width)
        found->second.resize(found->second.size() - width);
    }
  }
  std::vector<Vec3> position(n), velocity(n);
  std::vector<std::uint32_t> species(n);
  std::vector<double> radius(n);
  for (std::size_t i = 0; i < n; ++i) {
    position[i] = sim.position(i);
    velocity[i] = sim.velocity(i);
    species[i] = p.species[i];
    radius[i] = p.radius[i];
  }
  SeriesRow row;
  const std::int32_t mixing = scene_.analysis.mixing_species;
  if (mixing >= 0) {
    std::vector<Vec3> now, start;
    std::vector<char> tags;
    for (std::size_t i = 0; i < n; ++i) {
      if (static_cast<std::int32_t>(species[i]) != mixing) continue;
      const std::size_t r = rank_of(ids_, p.id[i]);
      if (r == kNotAtStart) continue;  // entered later: no start height, no tag
      now.push_back(position[i]);
      tags.push_back(tagged_[r]);
      Vec3 origin = position[i];
      origin[vertical_] = start_height_[r];
      start.push_back(origin);
    }
    row.push_back({"lacey_index",
                   0,
                   {lacey_index(now, tags, mixing_grid_, scene_.analysis.min_particles).index}});
    // Displacements about their mean: a narrow bed rises and falls as a whole (a plug), which
    // moves every particle alike and says nothing about dispersion.
    double shift = 0.0;
    for (std::size_t k = 0; k < now.size(); ++k) shift += now[k][vertical_] - start[k][vertical_];
    if (!now.empty()) shift /= static_cast<double>(now.size());
    for (Vec3& origin : start) origin[vertical_] += shift;
    row.push_back({"axial_msd", 0, {mean_squared_displacement(now, start, vertical_)}});
  }
  if (small_ >= 0)
    row.push_back({"segregation_index",
                   0,
                   {segregation_index(position, species, static_cast<std::uint32_t>(small_),
                                      static_cast<std::uint32_t>(large_), floor_, vertical_)}});
  const LocalFields fields = local_fields(position, velocity, species, radius, S, field_grid_);
  row.push_back({"granular_temperature", S, species_granular_temperature(fields)});
  row.push_back({"kinetic_collision_rate", S * S, kinetic_collision_frequencies(fields)});
  row.push_back({"kinetic_impact_rate", S * S,
                 kinetic_collision_frequencies(fields, scene_.system.impact_speed)});
  if (gas != nullptr) {
    std::vector<double> u, f, eps;
    std::vector<std::size_t> count(S, 0);
    for (std::uint32_t s : species) ++count[s];
    for (std::uint32_t s = 0; s < S; ++s) {
      // A species with no particles sees nothing; before the first fluid step nothing is seen.
      if (count[s] == 0 || gas->times().steps == 0) {
        u.insert(u.end(), 3, NAN);
        f.insert(f.end(), 3, NAN);
        eps.push_back(NAN);
        continue;
      }
      const Vec3 us = gas->mean_gas_velocity_at(s), fs = gas->mean_gas_force_on(s);
      u.insert(u.end(), {us.x(), us.y(), us.z()});
      f.insert(f.end(), {fs.x(), fs.y(), fs.z()});
      eps.push_back(gas->mean_porosity_at(s));
    }
    row.push_back({"gas_velocity_seen", 3 * S, u});
    row.push_back({"gas_force_mean", 3 * S, f});
    row.push_back({"porosity_seen", S, eps});
  }
  if (!profiles_.heights.empty()) {
    std::vector<Vec3> spin(n);
    for (std::size_t i = 0; i < n; ++i) spin[i] = sim.spin(i);
    row.push_back({"profile_sums", profiles_.row_width(),
                   profile_sums(profiles_, position, velocity, spin, radius)});
  }
  if (plugs_.bins > 0) {
    // Heights of the particles of t = 0 by id (NaN for one that left).
    std::vector<double> height(n), by_id(ids_.size(), NAN);
    for (std::size_t i = 0; i < n; ++i) {
      height[i] = position[i][vertical_];
      const std::size_t r = rank_of(ids_, p.id[i]);
      if (r != kNotAtStart) by_id[r] = height[i];
    }
    row.push_back({"axial_solid_fraction", static_cast<std::size_t>(plugs_.bins),
                   axial_solid_fraction(height, radius, plugs_.bottom, plugs_.bin, plugs_.bins,
                                        plugs_.area)});
    row.push_back({"plug_height", ids_.size(), by_id});
  }
  if (bed_enabled_) {
    BedSample bed = sample_bed(bed_, sim, gas);
    row.push_back({"bed_height", bed_.height_width(), std::move(bed.heights)});
    if (bed_.gas) row.push_back({"bed_pressure", 3, std::move(bed.pressure)});
    if (bed_.gas && bed_.probe_width() > 0)
      row.push_back({"bed_probe_pressure", bed_.probe_width(), std::move(bed.probes)});
    row.push_back({"bed_map_sums", bed_.map_width(), std::move(bed.map)});
  }
  if (!tagged_ids_.empty()) {
    const std::vector<double>& previous = history_["tagged_impulse"];
    const std::size_t width = 3 * tagged_ids_.size() * tagged_partners_;
    const bool has_previous = !times_.empty() && previous.size() >= width * times_.size();
    sample_tagged_bodies(sim,
                         has_previous ? previous.data() + (times_.size() - 1) * width : nullptr,
                         has_previous ? times_.back() : t, row);
  }
  times_.push_back(t);
  for (const SeriesColumn& c : row) {
    std::vector<double>& h = history_[c.name];
    h.insert(h.end(), c.values.begin(), c.values.end());
  }
  return row;
}

RunAnalysis::Conclusions RunAnalysis::conclude(const CollisionMethod& sim) const {
  const System& system = sim.system();
  const std::size_t S = system.species.size();
  Conclusions c;
  c.duration = sim.time();
  c.count.assign(S, 0);
  for (std::size_t i = 0; i < sim.particle_count(); ++i) ++c.count[system.particles.species[i]];
  auto series = [&](const char* name) -> const std::vector<double>* {
    auto found = history_.find(name);
    return found != history_.end() && found->second.size() >= times_.size() && !times_.empty()
               ? &found->second
               : nullptr;
  };
  if (const auto* lacey = series("lacey_index")) {
    c.mixing = true;
    c.lacey_start = lacey->front();
    // The fit starts where the data start (the measured M(0)), not at M = 0.
    const double start = times_.front() == 0.0 && std::isfinite(c.lacey_start) ? c.lacey_start : 0.0;
    c.rate = fit_mixing_rate(times_, *lacey, start);
    c.lacey_end = lacey->back();
  }
  if (const auto* msd = series("axial_msd")) {
    // Saturation: two independent heights of the mixed bed differ by 2 Var(h) in the mean.
    std::vector<double> heights;
    for (std::size_t i = 0; i < sim.particle_count(); ++i)
      if (static_cast<std::int32_t>(system.particles.species[i]) == scene_.analysis.mixing_species)
        heights.push_back(sim.position(i)[vertical_]);
    const double mean =
        std::accumulate(heights.begin(), heights.end(), 0.0) / static_cast<double>(heights.size());
    double var = 0.0;
    for (double h : heights) var += (h - mean) * (h - mean);
    c.saturation_msd = 2.0 * var / static_cast<double>(heights.size());
    if (c.saturation_msd > 0.0) {
      c.dispersion = fit_confined_dispersion(times_, *msd, c.saturation_msd);
      c.early_dispersion = fit_dispersion(times_, *msd, c.saturation_msd);
    }
  }
  const RunStatistics& st = sim.statistics();
  const double g = system.flight.gravity.norm();
  c.measured_rate.assign(S * S, NAN);
  c.impact_rate.assign(S * S, NAN);
  c.wall_impact_rate.assign(S, NAN);
  c.impulse_rate.assign(S * S, NAN);
  c.wall_rate.assign(S, NAN);
  c.weight.assign(S, 0.0);
  // Particle-seconds of each species since t = 0: the count times the duration, or with inflow
  // and outflow the time integral of the number present.
  std::vector<double> particle_seconds(S);
  for (std::size_t s = 0; s < S; ++s)
    particle_seconds[s] = static_cast<double>(c.count[s]) * c.duration;
  if (flow_ != nullptr) particle_seconds = flow_->particle_seconds_at(sim.time());
  for (std::size_t s = 0; s < S; ++s) {
    c.weight[s] = system.species[s].mass() * g;
    if (!(particle_seconds[s] > 0.0)) continue;
    const double per = 1.0 / particle_seconds[s];
    for (std::size_t t = 0; t < S; ++t) {
      // Each s-s collision involves two particles of s.
      c.measured_rate[s * S + t] = static_cast<double>(st.pair(s, t)) * (s == t ? 2.0 : 1.0) * per;
      c.impact_rate[s * S + t] = static_cast<double>(st.pair_impact(s, t)) * (s == t ? 2.0 : 1.0) * per;
      c.impulse_rate[s * S + t] = st.impulse(s, t) * (s == t ? 2.0 : 1.0) * per;
    }
    std::uint64_t walls = 0, wall_impacts = 0;
    for (std::size_t w = 0; w < st.wall_count; ++w) {
      walls += st.wall(s, w);
      wall_impacts += st.wall_impact(s, w);
    }
    c.wall_rate[s] = static_cast<double>(walls) * per;
    c.wall_impact_rate[s] = static_cast<double>(wall_impacts) * per;
  }
  c.kinetic_rate.assign(S * S, NAN);
  if (const auto* k = series("kinetic_collision_rate"))
    for (std::size_t j = 0; j < S * S; ++j) c.kinetic_rate[j] = time_average(times_, *k, S * S, j);
  c.kinetic_impact_rate.assign(S * S, NAN);
  if (const auto* k = series("kinetic_impact_rate"))
    for (std::size_t j = 0; j < S * S; ++j)
      c.kinetic_impact_rate[j] = time_average(times_, *k, S * S, j);
  c.temperature.assign(S, NAN);
  if (const auto* T = series("granular_temperature"))
    for (std::size_t s = 0; s < S; ++s) c.temperature[s] = time_average(times_, *T, S, s);
  if (const auto* seg = series("segregation_index")) {
    c.segregation_start = seg->front();
    c.segregation_end = seg->back();
    c.segregation_mean = time_average(times_, *seg, 1, 0);
  }
  if (const auto* u = series("gas_velocity_seen")) {
    c.gas = true;
    const auto* f = series("gas_force_mean");
    const auto* eps = series("porosity_seen");
    for (std::size_t s = 0; s < S; ++s) {
      Vec3 us, fs;
      for (int k = 0; k < 3; ++k) {
        us[k] = time_average(times_, *u, 3 * S, 3 * s + static_cast<std::size_t>(k));
        fs[k] = f != nullptr ? time_average(times_, *f, 3 * S, 3 * s + static_cast<std::size_t>(k))
                             : NAN;
      }
      c.gas_velocity.push_back(us);
      c.gas_force.push_back(fs);
      c.porosity.push_back(eps != nullptr ? time_average(times_, *eps, S, s) : NAN);
    }
  }
  if (!tagged_ids_.empty()) {
    const auto* v = series("tagged_mean_velocity");
    const auto* impulse = series("tagged_impulse");
    if (v != nullptr && impulse != nullptr)
      c.tagged = conclude_tagged(tagged_ids_, tagged_partners_, times_, *v, *impulse);
  }
  if (const auto* sums = profiles_.heights.empty() ? nullptr : series("profile_sums")) {
    c.has_profiles = true;
    c.profiles = conclude_profiles(profiles_, times_, *sums);
  }
  if (plugs_.bins > 0) {
    const auto* profiles = series("axial_solid_fraction");
    const auto* heights = series("plug_height");
    if (profiles != nullptr && heights != nullptr)
      c.plugs = conclude_plugs(plugs_, times_, *profiles, *heights, ids_.size());
  }
  if (bed_enabled_) {
    const auto* heights = series("bed_height");
    const auto* map = series("bed_map_sums");
    const auto* pressure = series("bed_pressure");
    const auto* probes = series("bed_probe_pressure");
    const std::vector<double> none;
    if (heights != nullptr && map != nullptr) {
      c.has_bed = true;
      c.bed = conclude_bed(bed_, times_, *heights, pressure != nullptr ? *pressure : none,
                           probes != nullptr ? *probes : none, *map);
    }
  }
  return c;
}

}  // namespace carom
