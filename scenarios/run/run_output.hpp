#pragma once
/// The HDF5 file of one run (plus its XDMF sidecars) and checkpoints.
///
/// Layout of a run file (all SI; tensors are 9 values row by row: xx xy xz yx ... zz):
///   /                    attributes: kind = "carom run", carom_version, seed, scene_name
///   /scene               string: the scene file text as run (after --set overrides)
///   /domain/             lower (3), upper (3), periodic (3, 0/1), gravity (3); attribute volume
///   /species/            name, diameter, density, mass, count (S each; count at creation)
///   /walls/name          names of the walls (W; collision counters refer to them by index)
///   /snapshots/NNNNNN/   one group per snapshot, attribute time (s), rows in id order:
///                        position, velocity, spin (N x 3), radius (N), species (N, int32),
///                        id (N, int64)
///   /timeseries/         extendible datasets, one row per sample:
///     time; kinetic_translational, kinetic_rotational, potential, dissipated, total_energy (J);
///     events, collisions (uint64, cumulative); event_rate, collision_rate (1/s over the
///     interval since the previous sample); virial (x9, cumulative sum r_ij (x) J_i, J s);
///     kinetic_stress (x9, sum m v v / V at the sample, Pa); pressure_tensor (x9, Pa: the
///     kinetic stress averaged over the interval by the trapezoidal rule plus the virial booked
///     in the interval / (V dt)); pressure (trace / 3, Pa); pair_collisions (x S*S, uint64,
///     cumulative, symmetric); pair_impacts (x S*S, uint64, cumulative, symmetric: the
///     collisions above the impact speed, scenarios/scene/impact_speed.hpp); pair_impulse (x S*S, cumulative sum of |J| over the collisions
///     of each species pair, N s, symmetric); and when there are walls wall_collisions and
///     wall_impacts (x S*W, uint64, cumulative) and wall_impulse (x W*3, cumulative, N s). V is the box volume.
///   /analysis/          (runs with an analysis) id, tagged, start_height (by particle id),
///                        mixing_grid/ and field_grid/ (lower, upper, cells); the analysis
///                        series (run_analysis.hpp) are in /timeseries beside the others
///   /xdmf/vertices_N     0 .. N-1 (int64): the connectivity of the sidecar's N vertex cells
/// The XDMF sidecars (xdmf_sidecar.hpp) beside it: run.xmf lists the snapshots' particles as a
/// time series of vertex cells with radius, velocity, spin, species and id as point data, and
/// with a gas run_gas.xmf lists the gas fields as cell data; both are rewritten (atomically)
/// after every snapshot.
///
/// Both files also carry the run's identity as root attributes: method, run_id, scene_hash
/// (RunInfo). A checkpoint ends with the root attribute checksum (file_checksum.hpp), written last
/// and verified before anything else is read.
///
/// Layout of a checkpoint: root attributes kind = "carom checkpoint", carom_version, seed,
/// scene_name; /scene; /state: the method's state, attribute method = its kind (for the
/// event-driven engine see events/event_driven/engine_state.hpp); /gas: the gas's state when
/// the scene has one (named datasets, fluid/coupling_state.cpp); /flow: the inflows' and
/// outflows' state when the scene has them (events/flow/). Doubles are stored as native
/// doubles: bit for bit.
#include <cstdint>
#include <memory>
#include <string>

#include "events/flow/flow_boundaries.hpp"
#include "events/method.hpp"
#include "fluid/coupling.hpp"
#include "scenarios/analysis/run_analysis.hpp"

namespace carom {

/// What identifies a run in its outputs: run.h5, checkpoint.h5 and summary.json carry the same
/// identity, and `carom resume` refuses a run file and a checkpoint whose identities differ.
struct RunInfo {
  std::string scene_text;   ///< The scene file text (after overrides).
  std::string scene_name;   ///< [meta] name.
  std::uint64_t seed = 0;   ///< Random seed.
  std::string method{};     ///< The collision method's kind (empty: not recorded).
  std::uint64_t run_id = 0; ///< Random number drawn when the run started (0: not recorded).
  /// Hash of scene_text (text_hash), so two runs of different scenes differ at a glance.
  std::uint64_t scene_hash() const;
};

/// Writes one run's HDF5 file. Opening creates (truncates) the file. The time series' rows wait
/// in memory and are written together: with each snapshot, by write_waiting_rows (the run loop
/// calls it before every checkpoint and at the end), and once the first of them has waited
/// kRowWait of wall time. Every write is flushed, so a crash leaves a readable file with
/// everything written so far: all but the last second's rows, never those before the last
/// checkpoint. (Flushing each row of a gas run cost 2-3 % of its time.)
class RunFile {
 public:
  /// Wall-clock seconds a row waits at most before it is written (once the run loop or a new
  /// row looks: write_overdue_rows).
  static constexpr double kRowWait = 1.0;
  /// `gas`: the run's gas (nullptr without one): its grid goes into /gas.
  RunFile(const std::string& path, const RunInfo& info, const System& system, const GasCoupling* gas = nullptr);
  /// Reopens an existing run file to append (used by `carom resume`). When the run resumes from
  /// a checkpoint older than the file's last outputs, the first snapshot / sample written drops
  /// those at or after its time, so the file ends as the uninterrupted run's would.
  static std::unique_ptr<RunFile> append(const std::string& path);
  /// Writes the rows that still wait (an error then is printed, not thrown).
  ~RunFile();
  RunFile(const RunFile&) = delete;
  RunFile& operator=(const RunFile&) = delete;

  /// Adds a snapshot of every particle at sim.time() and rewrites the XDMF sidecar.
  void write_snapshot(const CollisionMethod& sim, const GasCoupling* gas = nullptr);
  /// Appends one row of every time series at sim.time(); rates and the pressure tensor are
  /// averages over the interval since the previous row (since t = 0 for the first). `extra`:
  /// further series of this row (the run's analysis), created at their first row.
  void append_sample(const CollisionMethod& sim, const GasCoupling* gas = nullptr, const SeriesRow& extra = {});
  /// Writes the rows that wait and flushes the file (nothing when none waits).
  void write_waiting_rows();
  /// write_waiting_rows once the first waiting row has waited the row wait (kRowWait).
  void write_overdue_rows();
  /// The row wait in wall-clock seconds (kRowWait unless set; 0: each row written at once).
  void set_row_wait(double seconds);
  const std::string& path() const;

 private:
  RunFile();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Writes a checkpoint atomically (to a temporary file, then renamed over `path`), so a crash
/// while writing never destroys the previous checkpoint.
void write_checkpoint(const std::string& path, const CollisionMethod& sim, const RunInfo& info,
                      const GasCoupling* gas = nullptr, const FlowBoundaries* flow = nullptr);

/// A checkpoint read back: what identifies the run, and the file kept open for the method's
/// state (restore_method) and the gas's.
struct Checkpoint {
  RunInfo info;
  std::shared_ptr<const h5::File> file;  ///< The checkpoint, open read-only.
  /// The method's saved state (CollisionMethod::save_state), for restore_method.
  h5::Group method_state() const { return file->open_group("state"); }
  /// Whether the run had a gas, and its saved state (GasCoupling::save), for attach_gas.
  bool has_gas() const { return file->contains("gas"); }
  h5::Group gas_state() const { return file->open_group("gas"); }
  /// Whether the run had inflows or outflows, and their saved state (FlowBoundaries::save).
  bool has_flow() const { return file->contains("flow"); }
  h5::Group flow_state() const { return file->open_group("flow"); }
};
/// Opens a checkpoint, verifies its checksum first (std::runtime_error naming the file when it
/// is missing or differs) and reads what identifies the run.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace carom
