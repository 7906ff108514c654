#pragma once
/// The XDMF sidecars of a run file: light XML that lets ParaView (and VisIt) read the snapshots
/// of run.h5 as a time series.
///
///   run.xmf      the particles: one unstructured grid per snapshot, one vertex cell per
///                particle (Polyvertex topology, one node per element, connectivity
///                /xdmf/vertices_N of the run file), radius, velocity, spin, species and id as
///                point data.
///   run_gas.xmf  (runs with a gas) the gas: one uniform grid per snapshot, the porosity,
///                pressure and velocity of each gas cell as cell data.
///
/// Why two files and the explicit connectivity (measured with Debian's ParaView 5.11): its
/// default reader for .xmf ("Xdmf3 Reader (Top Level Partition)", Xdmf3ReaderS) flattens every
/// file holding more than one grid into a single unnamed multipiece, so particles and gas in one
/// file come out mixed and unnamed; and both Xdmf3 readers make no cells from a Polyvertex
/// topology without connectivity (points only: nothing renders as a surface). One grid per
/// file with explicit connectivity reads the same in all three of its readers (Xdmf3ReaderS,
/// Xdmf3ReaderT and the legacy XDMFReader): tests/paraview checks it.
#include <array>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "core/vec3.hpp"

namespace carom {

/// One snapshot as the sidecars reference it.
struct XdmfSnapshot {
  std::string name;   ///< Group name under /snapshots (six digits).
  double time;        ///< Simulated time of the snapshot, s.
  std::size_t count;  ///< Particles in the snapshot.
};

/// The gas grid of a run (cell-centred fields; x varies fastest in the datasets).
struct XdmfGasGrid {
  std::array<int, 3> cells{0, 0, 0};  ///< Cells along x, y, z.
  Vec3 lower = Vec3::Zero();          ///< Lower corner of the grid, m.
  Vec3 spacing = Vec3::Zero();        ///< Cell size along x, y, z, m.
};

/// "run.h5" -> "run_gas.xmf" (any other name gets "_gas.xmf" appended).
std::string gas_xdmf_path_of(const std::string& h5_path);

/// Path in the run file of the connectivity of `count` vertex cells: 0, 1, ..., count - 1.
std::string vertex_dataset_of(std::size_t count);

/// Writes the connectivity for snapshots of `count` particles into the run file, unless it is
/// there already (a run's count does not change: one dataset of 8 * count bytes per run).
void write_vertex_cells(const h5::File& file, std::size_t count);

/// Appends one snapshot to the sidecars beside `h5_path` in O(1): its grid is written over
/// their closing tail, followed by the tail, so each file stays whole XML after every snapshot
/// without being rewritten. False (nothing changed) when a sidecar does not end as carom
/// writes it (then rewrite them with write_xdmf_sidecars). Throws std::runtime_error when a
/// write fails (the tail is put back).
bool append_xdmf_snapshot(const std::string& h5_path, const XdmfSnapshot& snapshot, const XdmfGasGrid* gas);

/// Rewrites run.xmf (and, when `gas` is given, run_gas.xmf) beside the run file `h5_path` so
/// that they list `snapshots`; each file is written aside and renamed over the old one, so a
/// viewer never reads half a file.
void write_xdmf_sidecars(const std::string& h5_path, const std::vector<XdmfSnapshot>& snapshots,
                         const XdmfGasGrid* gas);

}  // namespace carom
