#pragma once
/// The HDF5 file of one run (plus its XDMF sidecar) and checkpoints.
///
/// Layout of a run file (all SI):
///   /               attributes: carom_version, seed, scene_name
///   /scene          string dataset: the scene file text as run (after --set overrides)
///   /species        compound or parallel datasets: name, diameter, density
///   /walls          names of the walls (collision counters refer to them by index)
///   /snapshots/NNNNNN   group per snapshot, attribute time; datasets position (N x 3),
///                   velocity (N x 3), spin (N x 3), radius (N), species (N), id (N)
///   /timeseries/    extendible 1-D datasets, one row per sample: time, kinetic_translational,
///                   kinetic_rotational, potential, dissipated, events, collisions,
///                   event_rate, pressure_tensor (rows x 9), pair_collisions (rows x S*S),
///                   wall_collisions (rows x S*W)
/// The XDMF sidecar (same name, .xmf) lists the snapshots as a temporal collection of
/// polyvertex grids with radius, velocity, spin, species and id as point data.
#include <cstdint>
#include <memory>
#include <string>

#include "events/simulator.hpp"

namespace carom {

/// What identifies a run in its outputs.
struct RunInfo {
  std::string scene_text;   ///< The scene file text (after overrides).
  std::string scene_name;   ///< [meta] name.
  std::uint64_t seed = 0;   ///< Random seed.
};

/// Writes one run's HDF5 file. Opening creates (truncates) the file; every write is flushed so
/// that a crash leaves a readable file with everything written so far.
class RunFile {
 public:
  RunFile(const std::string& path, const RunInfo& info, const System& system);
  /// Reopens an existing run file to append (used by `carom resume`).
  static std::unique_ptr<RunFile> append(const std::string& path);
  ~RunFile();
  RunFile(const RunFile&) = delete;
  RunFile& operator=(const RunFile&) = delete;

  /// Adds a snapshot of every particle at sim.time() and rewrites the XDMF sidecar.
  void write_snapshot(const Simulator& sim);
  /// Appends one row of every time series at sim.time().
  void append_sample(const Simulator& sim);
  const std::string& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Writes a checkpoint atomically (to a temporary file, then renamed over `path`), so a crash
/// while writing never destroys the previous checkpoint.
void write_checkpoint(const std::string& path, const Simulator& sim, const RunInfo& info);

/// A checkpoint read back.
struct Checkpoint {
  RunInfo info;
  EngineState state;
};
Checkpoint read_checkpoint(const std::string& path);

}  // namespace carom
