#include "scenarios/run/run_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "carom/version.hpp"
#include "core/hdf5.hpp"
#include "fluid/drag.hpp"
#include "scenarios/run/output_support.hpp"
#include "scenarios/run/xdmf_sidecar.hpp"

namespace carom {


using namespace output_detail;

namespace {
/// Shape of a gas field: (nz, ny, nx) or (nz, ny, nx, components) (x varies fastest).
std::vector<hsize_t> gas_shape(const std::array<int, 3>& cells, hsize_t components) {
  std::vector<hsize_t> shape{hsize_t(cells[2]), hsize_t(cells[1]), hsize_t(cells[0])};
  if (components > 0) shape.push_back(components);
  return shape;
}

// ---- time series ------------------------------------------------------------------------------

/// Columns of each time series (0: a 1-D series); uint64 series are listed separately.
struct SeriesLayout {
  std::vector<std::pair<std::string, hsize_t>> doubles;
  std::vector<std::pair<std::string, hsize_t>> counters;
};

/// Time series of a run with a gas: pressure drop over the domain (Pa; mean pressure at the
/// bottom face of the gas grid minus that at the top face, GasCoupling::pressure_drop),
/// superficial inlet velocity of each side that is an inlet (m/s, one column per side, 0
/// elsewhere), total drag on the particles (N), net rate of z-momentum the gas brings in through
/// the bottom and top per unit area (Pa, GasCoupling::momentum_inflow).
const std::vector<std::pair<std::string, hsize_t>> kGasSeries = {{"gas_pressure_drop", 0},
                                                                 {"gas_inlet_velocity", 6},
                                                                 {"gas_drag_force", 3},
                                                                 {"gas_momentum_inflow", 0}};

SeriesLayout series_layout(std::size_t species, std::size_t walls) {
  SeriesLayout layout;
  layout.doubles = {{"time", 0},
                    {"kinetic_translational", 0},
                    {"kinetic_rotational", 0},
                    {"potential", 0},
                    {"elastic", 0},
                    {"dissipated", 0},
                    {"gas_work", 0},
                    {"total_energy", 0},
                    {"event_rate", 0},
                    {"collision_rate", 0},
                    {"virial", 9},
                    {"kinetic_stress", 9},
                    {"pressure_tensor", 9},
                    {"pressure", 0}};
  layout.counters = {{"events", 0},
                     {"collisions", 0},
                     {"pair_collisions", species * species},
                     {"pair_impacts", species * species}};
  layout.doubles.emplace_back("pair_impulse", species * species);
  if (walls > 0) {
    layout.counters.emplace_back("wall_collisions", species * walls);
    layout.counters.emplace_back("wall_impacts", species * walls);
    layout.doubles.emplace_back("wall_impulse", walls * 3);
  }
  return layout;
}

/// sum_i m_i v_i v_i^T at the simulator's current time, J.
Eigen::Matrix3d kinetic_tensor(const CollisionMethod& sim) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  const ParticleStore& p = sim.system().particles;
  for (std::size_t i = 0; i < sim.particle_count(); ++i) {
    const Vec3 v = sim.velocity(i);
    sum += p.mass[i] * v * v.transpose();
  }
  return sum;
}

}  // namespace

// ---- RunFile ----------------------------------------------------------------------------------

struct RunFile::Impl {
  explicit Impl(h5::File opened) : file(std::move(opened)) {}

  h5::File file;
  std::string path;
  std::size_t species_count = 0;
  std::size_t wall_count = 0;
  double volume = 0;  ///< Box volume, m^3 (the pressure tensor's normalisation).
  bool has_gas = false;
  std::array<int, 3> gas_cells{0, 0, 0};
  Vec3 gas_lower = Vec3::Zero(), gas_spacing = Vec3::Zero();

  struct SnapshotEntry {
    std::string name;
    double time;
    std::size_t count;
  };
  std::vector<SnapshotEntry> snapshots;

  // The previous sample, for the averages over the sample interval.
  double previous_time = 0;
  std::uint64_t previous_events = 0;
  std::uint64_t previous_collisions = 0;
  Eigen::Matrix3d previous_virial = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d previous_kinetic_stress = Eigen::Matrix3d::Zero();
  bool has_previous = false;

  // The time series' datasets, opened once (a sample appends to some twenty of them), each with
  // its rows that wait to be written; an empty dataset is a column this file does not have (one
  // written before the column existed).
  struct Column {
    std::optional<h5::Dataset> set;
    std::vector<double> doubles;          ///< Waiting values of a floating-point column.
    std::vector<std::uint64_t> counters;  ///< Waiting values of a counter column.
    void hold(const std::vector<double>& values) {
      doubles.insert(doubles.end(), values.begin(), values.end());
    }
    void hold(const std::vector<std::uint64_t>& values) {
      counters.insert(counters.end(), values.begin(), values.end());
    }
  };
  std::map<std::string, Column, std::less<>> columns;
  /// The column `name`, or nullptr when the file has none.
  Column* column(const std::string& name);
  /// Rows of the time series, written and waiting (the one being put included).
  std::size_t rows();
  // Rows wait in memory (RunFile::write_waiting_rows); the first of them since this instant.
  std::size_t waiting_rows = 0;
  std::chrono::steady_clock::time_point waiting_since;
  double row_wait = RunFile::kRowWait;
  /// Writes the waiting rows, then flushes the file.
  void flush();

  /// Brings run.xmf (and run_gas.xmf) up to date with `snapshots`.
  void write_xdmf() const;
  /// Snapshots the sidecars on disk list (0 also when unknown: they are rewritten).
  mutable std::size_t xdmf_listed = 0;
  void recover_previous_sample();
  void drop_samples_from(double time);
  void drop_snapshots_from(double time);
};

RunFile::RunFile(const std::string& path, const RunInfo& info, const System& system,
                 const GasCoupling* gas)
    : impl_(std::make_unique<Impl>(h5::File::create(path))) {
  Impl& d = *impl_;
  d.path = path;
  d.species_count = system.species.size();
  d.wall_count = system.walls.size();
  d.volume = system.domain.volume();
  write_info(d.file, info, kRunKind);

  const h5::Group domain = d.file.create_group("domain");
  domain.write<double>("lower",
                       {system.domain.lower.x(), system.domain.lower.y(), system.domain.lower.z()});
  domain.write<double>("upper",
                       {system.domain.upper.x(), system.domain.upper.y(), system.domain.upper.z()});
  domain.write<std::int32_t>("periodic", {system.domain.periodic[0], system.domain.periodic[1],
                                          system.domain.periodic[2]});
  domain.write<double>(
      "gravity", {system.flight.gravity.x(), system.flight.gravity.y(), system.flight.gravity.z()});
  domain.set_attribute("volume", d.volume);

  const h5::Group species = d.file.create_group("species");
  std::vector<std::string> names;
  std::vector<double> diameter, density, mass;
  std::vector<std::uint64_t> count(system.species.size(), 0);
  for (const Species& s : system.species) {
    names.push_back(s.name);
    diameter.push_back(s.diameter);
    density.push_back(s.density);
    mass.push_back(s.mass());
  }
  for (std::uint32_t s : system.particles.species) ++count.at(s);
  species.write_strings("name", names);
  species.write("diameter", diameter);
  species.write("density", density);
  species.write("mass", mass);
  species.write("count", count);

  const h5::Group walls = d.file.create_group("walls");
  std::vector<std::string> wall_names;
  for (const Wall& w : system.walls) wall_names.push_back(w.name);
  walls.write_strings("name", wall_names);

  d.file.create_group("snapshots");
  const h5::Group series = d.file.create_group("timeseries");
  const SeriesLayout layout = series_layout(d.species_count, d.wall_count);
  for (const auto& [name, columns] : layout.doubles)
    series.create_extendible<double>(name, columns);
  for (const auto& [name, columns] : layout.counters)
    series.create_extendible<std::uint64_t>(name, columns);
  if (gas != nullptr) {
    d.has_gas = true;
    d.gas_cells = gas->cells();
    d.gas_lower = gas->grid_lower();
    d.gas_spacing = gas->cell_size();
    const h5::Group group = d.file.create_group("gas");
    group.write<std::int32_t>("cells", {d.gas_cells[0], d.gas_cells[1], d.gas_cells[2]});
    group.write<double>("lower", {d.gas_lower.x(), d.gas_lower.y(), d.gas_lower.z()});
    group.write<double>("spacing", {d.gas_spacing.x(), d.gas_spacing.y(), d.gas_spacing.z()});
    group.write("open_volume", gas->open_volume(), gas_shape(d.gas_cells, 0));
    group.write_string("closure", std::string(drag_closure_name(gas->settings().closure)));
    group.set_attribute("density", gas->settings().density);
    group.set_attribute("viscosity", gas->settings().viscosity);
    group.set_attribute("time_step", gas->settings().time_step);
    // Minimum fluidization of the first species: the closure's own prediction for a bed at
    // eps_mf = 0.4 and the Wen-Yu correlation (superficial velocities, m/s).
    if (!system.species.empty() && system.flight.has_gravity()) {
      const Species& s = system.species[0];
      const double g = system.flight.gravity.norm();
      DragInput in;
      in.diameter = in.sauter_diameter = s.diameter;
      in.gas_density = gas->settings().density;
      in.gas_viscosity = gas->settings().viscosity;
      in.particle_density = s.density;
      const DragClosure closure(gas->settings().closure, gas->settings().fluidization_porosity, g);
      group.set_attribute("closure_minimum_fluidization", closure.minimum_fluidization_velocity(in, 0.4));
      group.set_attribute("wen_yu_minimum_fluidization", wen_yu_minimum_fluidization_velocity(in, g));
    }
    for (const auto& [name, columns] : kGasSeries) series.create_extendible<double>(name, columns);
  }
  d.file.flush();
  d.write_xdmf();
}

std::unique_ptr<RunFile> RunFile::append(const std::string& path) {
  std::unique_ptr<RunFile> run(new RunFile());
  run->impl_ = std::make_unique<Impl>(h5::File::open(path, true));
  Impl& d = *run->impl_;
  read_info(d.file, kRunKind);
  d.path = path;
  d.species_count = d.file.open_group("species").open_dataset("diameter").size();
  d.wall_count = d.file.open_group("walls").open_dataset("name").size();
  d.volume = d.file.open_group("domain").attribute<double>("volume");
  if (d.file.contains("gas")) {
    const h5::Group gas = d.file.open_group("gas");
    const auto cells = gas.read<std::int32_t>("cells", {3});
    const auto lower = gas.read<double>("lower", {3});
    const auto spacing = gas.read<double>("spacing", {3});
    d.has_gas = true;
    d.gas_cells = {cells[0], cells[1], cells[2]};
    d.gas_lower = Vec3(lower[0], lower[1], lower[2]);
    d.gas_spacing = Vec3(spacing[0], spacing[1], spacing[2]);
  }
  const h5::Group snapshots = d.file.open_group("snapshots");
  for (const std::string& name : snapshots.children()) {
    const h5::Group snapshot = snapshots.open_group(name);
    d.snapshots.push_back(
        {name, snapshot.attribute<double>("time"), snapshot.open_dataset("radius").size()});
  }
  d.recover_previous_sample();
  return run;
}

RunFile::RunFile() = default;

RunFile::~RunFile() {
  // The run loop writes the rows before it returns; here only for a run ended otherwise.
  if (!impl_ || impl_->waiting_rows == 0) return;
  try {
    impl_->flush();
  } catch (const std::exception& e) {
    std::cerr << "carom: " << impl_->path << ": the last " << impl_->waiting_rows
              << " rows of the time series could not be written: " << e.what() << "\n";
  }
}

void RunFile::write_waiting_rows() {
  if (impl_->waiting_rows > 0) impl_->flush();
}

void RunFile::write_overdue_rows() {
  const Impl& d = *impl_;
  if (d.waiting_rows > 0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - d.waiting_since).count() >=
          d.row_wait)
    write_waiting_rows();
}

void RunFile::set_row_wait(double seconds) {
  impl_->row_wait = seconds;
  write_overdue_rows();
}

const std::string& RunFile::path() const {
  return impl_->path;
}

void RunFile::Impl::recover_previous_sample() {
  const h5::Group series = file.open_group("timeseries");
  const std::vector<double> times = series.read<double>("time");
  if (times.empty()) return;
  const std::size_t last = times.size() - 1;
  // Row `last` of a column of `width` values per row. A column may hold more rows than the time
  // (a run stopped while its columns were being appended: the resume truncates them), not fewer.
  auto row = [&]<class T>(const std::string& name, std::size_t width, T) {
    const std::vector<T> values = series.read<T>(name);
    if (values.size() < width * times.size())
      throw std::runtime_error(path + ": /timeseries/" + name + " holds " + std::to_string(values.size()) +
                               " values for " + std::to_string(times.size()) + " rows of " + std::to_string(width) +
                               ": the run file is damaged");
    return std::vector<T>(values.begin() + static_cast<std::ptrdiff_t>(width * last),
                          values.begin() + static_cast<std::ptrdiff_t>(width * (last + 1)));
  };
  previous_time = times[last];
  previous_events = row("events", 1, std::uint64_t{})[0];
  previous_collisions = row("collisions", 1, std::uint64_t{})[0];
  previous_virial = from_row_major(row("virial", 9, 0.0));
  previous_kinetic_stress = from_row_major(row("kinetic_stress", 9, 0.0));
  has_previous = true;
}

RunFile::Impl::Column* RunFile::Impl::column(const std::string& name) {
  auto found = columns.find(name);
  if (found == columns.end()) {
    const h5::Group series = file.open_group("timeseries");
    Column column;
    if (series.contains(name)) column.set = series.open_dataset(name);
    found = columns.emplace(name, std::move(column)).first;
  }
  return found->second.set ? &found->second : nullptr;
}

std::size_t RunFile::Impl::rows() {
  const Column* times = column("time");
  return times != nullptr ? times->set->size() + times->doubles.size() : 0;
}

void RunFile::Impl::flush() {
  for (auto& [name, column] : columns) {
    if (!column.set) continue;
    if (!column.doubles.empty()) column.set->append(column.doubles);
    if (!column.counters.empty()) column.set->append(column.counters);
    column.doubles.clear();
    column.counters.clear();
  }
  waiting_rows = 0;
  file.flush();
}

// A run resumed from a checkpoint older than its last outputs writes them again (bit for bit the
// same, the run being deterministic): the rows and snapshots from then on are dropped first.
void RunFile::Impl::drop_samples_from(double time) {
  flush();
  const h5::Group series = file.open_group("timeseries");
  const std::vector<double> times = series.read<double>("time");
  const auto keep =
      static_cast<hsize_t>(std::lower_bound(times.begin(), times.end(), time) - times.begin());
  for (const std::string& name : series.children()) series.open_dataset(name).truncate(keep);
  has_previous = false;
  previous_time = 0;
  previous_events = previous_collisions = 0;
  previous_virial = previous_kinetic_stress = Eigen::Matrix3d::Zero();
  recover_previous_sample();
}

void RunFile::Impl::drop_snapshots_from(double time) {
  const h5::Group group = file.open_group("snapshots");
  while (!snapshots.empty() && snapshots.back().time >= time) {
    group.remove(snapshots.back().name);
    snapshots.pop_back();
  }
}

void RunFile::write_snapshot(const CollisionMethod& sim, const GasCoupling* gas) {
  Impl& d = *impl_;
  if (!d.snapshots.empty() && d.snapshots.back().time >= sim.time())
    d.drop_snapshots_from(sim.time());
  const ParticleStore& p = sim.system().particles;
  const std::size_t n = sim.particle_count();
  // Rows in the order of the particle ids, so that row k is the same particle in every snapshot.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return p.id[a] < p.id[b]; });

  std::vector<Vec3> position(n), velocity(n), spin(n);
  std::vector<double> radius(n);
  std::vector<std::int32_t> species(n);
  std::vector<std::int64_t> id(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    position[k] = sim.position(i);
    velocity[k] = sim.velocity(i);
    spin[k] = sim.spin(i);
    radius[k] = p.radius[i];
    species[k] = static_cast<std::int32_t>(p.species[i]);
    id[k] = static_cast<std::int64_t>(p.id[i]);
  }
  const std::string name = snapshot_name(d.snapshots.size());
  const h5::Group snapshot = d.file.open_group("snapshots").create_group(name);
  snapshot.set_attribute("time", sim.time());
  snapshot.write("position", flatten(position), {n, 3});
  snapshot.write("velocity", flatten(velocity), {n, 3});
  snapshot.write("spin", flatten(spin), {n, 3});
  snapshot.write("radius", radius);
  snapshot.write("species", species);
  snapshot.write("id", id);
  if (gas != nullptr && d.has_gas) {
    const h5::Group fields = snapshot.create_group("gas");
    fields.write("porosity", gas->porosity(), gas_shape(d.gas_cells, 0));
    fields.write("pressure", gas->pressure_field(), gas_shape(d.gas_cells, 0));
    fields.write("velocity", flatten(gas->velocity_field()), gas_shape(d.gas_cells, 3));
  }
  write_vertex_cells(d.file, n);
  d.snapshots.push_back({name, sim.time(), n});
  d.flush();  // with the rows waiting
  d.write_xdmf();
}

void RunFile::append_sample(const CollisionMethod& sim, const GasCoupling* gas, const SeriesRow& extra) {
  Impl& d = *impl_;
  const double time = sim.time();
  if (d.has_previous && d.previous_time >= time) d.drop_samples_from(time);
  const Energies energy = sim.energies();
  const RunStatistics& stats = sim.statistics();
  const Eigen::Matrix3d kinetic_stress = kinetic_tensor(sim) / d.volume;

  // Averages over the interval since the previous sample: the collisional stress from the
  // virial booked in it, the kinetic stress by the trapezoidal rule on its two ends.
  const double interval = time - d.previous_time;
  const Eigen::Matrix3d collisional_stress =
      interval > 0.0 ? Eigen::Matrix3d((stats.virial - d.previous_virial) / (d.volume * interval))
                     : Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d mean_kinetic_stress =
      d.has_previous ? Eigen::Matrix3d(0.5 * (kinetic_stress + d.previous_kinetic_stress))
                     : kinetic_stress;
  const Eigen::Matrix3d pressure_tensor = mean_kinetic_stress + collisional_stress;
  auto rate = [&](std::uint64_t now, std::uint64_t before) {
    return interval > 0.0 ? static_cast<double>(now - before) / interval : 0.0;
  };

  // A run file written before a column existed (resumed with a newer carom) goes on without it.
  auto put = [&](const std::string& name, const auto& values) {
    if (Impl::Column* column = d.column(name)) column->hold(values);
  };
  put("time", std::vector<double>{time});
  put("kinetic_translational", std::vector<double>{energy.translational});
  put("kinetic_rotational", std::vector<double>{energy.rotational});
  put("potential", std::vector<double>{energy.potential});
  put("elastic", std::vector<double>{energy.elastic});
  put("dissipated", std::vector<double>{energy.dissipated});
  put("gas_work", std::vector<double>{energy.gas_work});
  put("total_energy", std::vector<double>{energy.total()});
  put("event_rate", std::vector<double>{rate(stats.events, d.previous_events)});
  put("collision_rate", std::vector<double>{rate(stats.collisions(), d.previous_collisions)});
  put("virial", row_major(stats.virial));
  put("kinetic_stress", row_major(kinetic_stress));
  put("pressure_tensor", row_major(pressure_tensor));
  put("pressure", std::vector<double>{pressure_tensor.trace() / 3.0});
  put("events", std::vector<std::uint64_t>{stats.events});
  put("collisions", std::vector<std::uint64_t>{stats.collisions()});
  put("pair_collisions", stats.pair_collisions);
  put("pair_impacts", stats.pair_impacts);
  put("pair_impulse", stats.pair_impulse);
  if (d.wall_count > 0) {
    put("wall_collisions", stats.wall_collisions);
    put("wall_impacts", stats.wall_impacts);
    put("wall_impulse",
        flatten(std::vector<Vec3>(stats.wall_impulse.begin(), stats.wall_impulse.end())));
  }
  if (d.has_gas) {
    std::vector<double> inlet(6, 0.0);
    double drop = 0.0, momentum_inflow = 0.0;
    Vec3 drag = Vec3::Zero();
    if (gas != nullptr) {
      for (int s = 0; s < 6; ++s) inlet[s] = gas->inlet_velocity(s, time);
      drop = gas->pressure_drop();
      drag = gas->total_drag();
      momentum_inflow = gas->momentum_inflow();
    }
    put("gas_pressure_drop", std::vector<double>{drop});
    put("gas_inlet_velocity", inlet);
    put("gas_drag_force", std::vector<double>{drag.x(), drag.y(), drag.z()});
    put("gas_momentum_inflow", std::vector<double>{momentum_inflow});
  }
  for (const SeriesColumn& column : extra) {
    if (d.column(column.name) == nullptr) {
      // A series that starts late would not line up with time: only at the first row.
      if (d.rows() > 1)
        throw std::logic_error("run file: series " + column.name + " added after the first row");
      d.file.open_group("timeseries").create_extendible<double>(column.name, column.columns);
      d.columns.erase(column.name);
    }
    put(column.name, column.values);
  }
  if (d.waiting_rows++ == 0) d.waiting_since = std::chrono::steady_clock::now();
  write_overdue_rows();

  d.previous_time = time;
  d.previous_events = stats.events;
  d.previous_collisions = stats.collisions();
  d.previous_virial = stats.virial;
  d.previous_kinetic_stress = kinetic_stress;
  d.has_previous = true;
}

void RunFile::Impl::write_xdmf() const {
  const XdmfGasGrid grid{gas_cells, gas_lower, gas_spacing};
  // One more snapshot than the sidecars list: appended in O(1). Otherwise (the first write, a
  // resumed run that dropped snapshots) they are rewritten whole.
  if (xdmf_listed + 1 == snapshots.size() && xdmf_listed > 0) {
    const SnapshotEntry& last = snapshots.back();
    if (append_xdmf_snapshot(path, {last.name, last.time, last.count}, has_gas ? &grid : nullptr)) {
      xdmf_listed = snapshots.size();
      return;
    }
  }
  xdmf_listed = 0;  // unknown while they are rewritten
  std::vector<XdmfSnapshot> entries;
  entries.reserve(snapshots.size());
  for (const SnapshotEntry& s : snapshots) entries.push_back({s.name, s.time, s.count});
  write_xdmf_sidecars(path, entries, has_gas ? &grid : nullptr);
  xdmf_listed = snapshots.size();
}

}  // namespace carom
