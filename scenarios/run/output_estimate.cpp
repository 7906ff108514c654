#include "scenarios/run/output_estimate.hpp"

#include <cmath>
#include <cstdio>
#include <numeric>
#include <system_error>
#include <vector>

#include "scenarios/scene/fill_capacity.hpp"
#include "scenarios/scene/initial_file.hpp"

namespace carom {

namespace fs = std::filesystem;

namespace {
/// Bytes of one particle's row in a snapshot: 10 doubles, an int32 species and an int64 id.
constexpr double kSnapshotParticleBytes = 10 * 8 + 4 + 8;
/// HDF5 objects of one snapshot group (group, six datasets, the time attribute) and its entry in
/// the XDMF sidecar (which is rewritten whole after every snapshot), bytes; measured: 2940 and
/// 1471 bytes per snapshot for a gas of 344 spheres written 1001 times (the sidecar's entry is
/// about 1640 bytes since it lists the cells' connectivity, 8 bytes per particle once per run).
constexpr double kSnapshotOverheadBytes = 4500;
/// The gas's share of a snapshot's overhead (group, three datasets, XDMF entry), bytes;
/// measured: 2000 and 1080 bytes for 20 beads on 80 gas cells written 51 times.
constexpr double kGasSnapshotOverheadBytes = 3000;
/// Values of the checkpoint's state per particle (position, velocity, spin, clock, radius,
/// counters, mass, inertia, last collision, species, id, cell, cell list place) and per gas cell.
constexpr double kCheckpointParticleBytes = 25 * 8;
constexpr double kCheckpointGasCellBytes = 25 * 8;
/// Every time series is chunked in about 8 KiB (core/hdf5.cpp), allocated at its first row.
constexpr double kSeriesChunkBytes = 8192;
/// The files' own metadata (root, /domain, /species, /walls, /gas groups), bytes.
constexpr double kFileOverheadBytes = 20000;

/// Instants k * every in [0, end] (up to round-off, as the run's schedule meets them), plus the
/// end itself when it is not one of them; first and last only for every = 0.
double instants(double end, double every) {
  if (every <= 0.0) return 2.0;
  const double last = std::floor(end / every * (1.0 + 1e-12));
  return last + 1.0 + (last * every < end * (1.0 - 1e-12) ? 1.0 : 0.0);
}
}  // namespace

std::size_t planned_particle_count(const Scene& scene) {
  const std::vector<std::size_t> counts = fill_counts(scene);
  check_fill_capacities(scene, counts);
  std::size_t n = scene.listed.size() + std::accumulate(counts.begin(), counts.end(), std::size_t{0});
  if (scene.from_file) n += read_initial_file(scene).size();
  return n;
}

OutputEstimate estimate_output(const Scene& scene, std::size_t particles) {
  // With inflows, as if every particle that enters by the end stayed: an upper bound.
  double entering = 0.0;
  for (const Inflow& in : scene.flow.inflows)
    entering += std::ceil(in.mass_flow * scene.end_time / scene.system.species[in.species].mass());
  const double n = static_cast<double>(particles) + entering;
  const double S = static_cast<double>(scene.system.species.size());
  const double W = static_cast<double>(scene.system.walls.size());
  const bool gas = scene.gas.coupling != CouplingLevel::None;
  const double cells = gas ? static_cast<double>(scene.gas.cells[0]) * scene.gas.cells[1] * scene.gas.cells[2] : 0.0;
  OutputEstimate e;
  e.snapshots = instants(scene.end_time, scene.output.snapshot_every);
  e.samples = instants(scene.end_time, scene.output.sample_every);
  e.snapshot_bytes = n * kSnapshotParticleBytes + kSnapshotOverheadBytes +
                     (gas ? cells * 5 * 8 + kGasSnapshotOverheadBytes : 0.0);
  // run_output.hpp: 12 scalar and tensor doubles (39 values), pair impulses, collisions and
  // impacts, events and collisions, wall collisions, impacts and impulses; the gas series (11
  // values); run_analysis.hpp: granular temperature, kinetic-theory collision and impact rates,
  // with a gas what each species sees, mixing, segregation. `series`: how many datasets they are.
  const bool mixing = scene.analysis.mixing_species >= 0;
  double values = 39 + 3 * S * S + 2 + (W > 0 ? 2 * S * W + 3 * W : 0.0);
  double series = 17 + (W > 0 ? 3 : 0);
  if (gas) values += 11 + 7 * S, series += 4 + 3;
  values += S + 2 * S * S + (S > 1 ? 1 : 0) + (mixing ? 2 : 0);
  series += 3 + (S > 1 ? 1 : 0) + (mixing ? 2 : 0);
  // tagged_bodies.hpp: T bodies, C = S + W partners: position, velocity, force (3 T each),
  // impulse and force by partner (3 T C each), the group's mean velocity and force (3 each).
  const double T = static_cast<double>(scene.analysis.tagged_bodies.size());
  if (T > 0) values += 9 * T + 6 * T * (S + W) + 6, series += 7;
  // bed_measures.hpp: the heights (one per share and the surface), with a gas the pressures (3)
  // and the probes, and the map sums (4 per bin).
  if (const BedSettings& bed = scene.analysis.bed; bed.enabled) {
    const double probes = static_cast<double>(bed.probes.size() + bed.probe_heights.size());
    values += static_cast<double>(bed.height_shares.size()) + 1 + 4.0 * bed.map_bins[0] * bed.map_bins[1];
    series += 2;
    if (gas) values += 3 + probes, series += 1 + (probes > 0 ? 1 : 0);
  }
  e.sample_bytes = values * 8;
  const double scene_text = static_cast<double>(scene.text.size());
  e.checkpoint_bytes = n * kCheckpointParticleBytes + cells * kCheckpointGasCellBytes + kFileOverheadBytes + scene_text;
  e.bytes = e.snapshots * e.snapshot_bytes + e.samples * e.sample_bytes + e.checkpoint_bytes +
            series * kSeriesChunkBytes + kFileOverheadBytes + scene_text;
  return e;
}

std::string byte_text(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
  int unit = 0;
  while (bytes >= 1000.0 && unit < 5) {
    bytes /= 1000.0;
    ++unit;
  }
  char text[48];
  std::snprintf(text, sizeof(text), unit == 0 ? "%.0f %s" : "%.3g %s", bytes, units[unit]);
  return text;
}

namespace {
/// "about 1.2 GB: 400 snapshots of ... (output.snapshot_every = ...) and ... over time.end = ...".
std::string estimate_parts(const Scene& scene, const OutputEstimate& e) {
  const OutputSchedule& out = scene.output;
  return "about " + byte_text(e.bytes) + ": " + format_number(e.snapshots) + " snapshots of " +
         byte_text(e.snapshot_bytes) + " (output.snapshot_every = " + format_number(out.snapshot_every) + " s) and " +
         format_number(e.samples) + " time-series rows of " + byte_text(e.sample_bytes) +
         " (output.sample_every = " + format_number(out.sample_every) + " s) over time.end = " +
         format_number(scene.end_time) + " s";
}
}  // namespace

std::string output_size_warning(const Scene& scene, const OutputEstimate& e) {
  if (e.bytes <= scene.output.warn_bytes) return "";
  return scene.file + ": the run will write " + estimate_parts(scene, e) + ", more than output.warn_bytes = " +
         byte_text(scene.output.warn_bytes) + ". Write snapshots and samples less often if that is more than you "
         "need, or raise output.warn_bytes (bytes) in [output] to silence this warning";
}

void check_output_size(const Scene& scene, const OutputEstimate& e, const fs::path& out_dir) {
  const OutputSchedule& out = scene.output;
  const std::string parts = estimate_parts(scene, e);
  if (e.bytes > out.max_bytes)
    throw SceneError(out.max_bytes_where + ": the run would write " + parts + ", more than output.max_bytes = " +
                     byte_text(out.max_bytes) + (out.max_bytes_given ? "" : " (the default)") +
                     ". Write snapshots and samples less often, or raise output.max_bytes (bytes) in [output]");
  if (out.max_bytes_given) return;
  // The free space where the directory will be: its nearest existing ancestor.
  std::error_code error;
  fs::path where = fs::absolute(out_dir, error);
  while (!where.empty() && !fs::exists(where, error) && where != where.parent_path()) where = where.parent_path();
  const fs::space_info space = fs::space(where, error);
  if (error) return;  // unknown: nothing to compare with
  if (e.bytes > static_cast<double>(space.available))
    throw SceneError(scene.file + ": the run would write " + parts + ", more than the " +
                     byte_text(static_cast<double>(space.available)) + " free on the file system of " +
                     where.string() + ". Write snapshots and samples less often, free space, or set "
                     "output.max_bytes (bytes) in [output] to run anyway");
}

}  // namespace carom
