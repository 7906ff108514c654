#pragma once
/// How much a run will write, estimated from its scene before it starts, and the refusal of runs
/// whose output would be too large (output.max_bytes, SCENES.md).
///
/// The estimate counts what run_output.hpp's layout stores: per snapshot every particle's
/// position, velocity and spin (9 doubles), radius (1 double), species (4 bytes) and id (8
/// bytes), with a gas its porosity, pressure and velocity in every cell (5 doubles), plus the
/// HDF5 objects of the snapshot group and its entry in the XDMF sidecar; per time-series row
/// the standard series, the gas series and the analysis series (8 bytes each value), and the
/// first chunk (8 KiB) of each series; and one checkpoint (the whole state, about 25 values per
/// particle and per gas cell). Snapshots are written at
/// k * snapshot_every and at the end (first and last only for 0), rows at k * sample_every and
/// at the end. The estimate is within about 15 % of the real size on the runs measured, which is
/// what a limit of gigabytes needs.
#include <cstddef>
#include <filesystem>
#include <string>

#include "scenarios/scene/scene.hpp"

namespace carom {

/// A run's output, estimated.
struct OutputEstimate {
  double snapshots = 0;       ///< Particle snapshots in run.h5.
  double samples = 0;         ///< Time-series rows.
  double snapshot_bytes = 0;  ///< One snapshot (particles, gas fields, HDF5 and XDMF overhead), bytes.
  double sample_bytes = 0;    ///< One row of every time series, bytes.
  double checkpoint_bytes = 0;  ///< checkpoint.h5, bytes.
  double bytes = 0;           ///< Everything: snapshots, rows, checkpoint, bytes.
};

/// The number of particles build_initial_state will create: listed, read from initial.from_file
/// and filled (fills too large for their region are refused here first, fill_capacity.hpp).
std::size_t planned_particle_count(const Scene& scene);

/// The output of `scene` with `particles` particles.
OutputEstimate estimate_output(const Scene& scene, std::size_t particles);

/// "1.2 GB", "31 MB", "850 kB" (decimal units).
std::string byte_text(double bytes);

/// Throws SceneError when the estimate exceeds output.max_bytes (10 GB unless given), or, unless
/// output.max_bytes is given, the free space of the file system that will hold `out_dir`.
/// The message names the scene's file and line, the estimate's parts and the key that raises it.
void check_output_size(const Scene& scene, const OutputEstimate& estimate, const std::filesystem::path& out_dir);

/// The warning to print before a run whose estimate exceeds output.warn_bytes (1 GB unless
/// given), with the estimate's parts and the keys that set it; empty when below.
std::string output_size_warning(const Scene& scene, const OutputEstimate& estimate);

}  // namespace carom
