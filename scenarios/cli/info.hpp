#pragma once
/// `carom info FILE.h5`: what a run file or checkpoint holds, without Python: a summary a
/// person reads (info.cpp), or with `--tree` the raw HDF5 tree (info_tree.cpp).
#include <ostream>
#include <string>

namespace carom {

/// Throws SceneError (exit code 2: the user gave the wrong file) when `path` does not exist,
/// is a directory or is not an HDF5 file.
void require_hdf5_file(const std::string& path);

/// The summary of a carom run file or checkpoint: scene name, carom version, seed, status (from
/// the summary.json beside it), species and counts, time range, snapshots and time-series rows,
/// the gas grid, and the headline numbers of summary.json when it is there. Throws SceneError
/// for a file that is not an HDF5 file or not one of carom's; std::runtime_error when a carom
/// file cannot be read.
void print_file_info(const std::string& path, std::ostream& out);

/// Prints the root attributes (version, seed, scene name), then every group and dataset with its
/// shape and, for groups, their attributes (snapshot times; only the first snapshot's contents).
/// Throws like print_file_info.
void print_file_tree(const std::string& path, std::ostream& out);

}  // namespace carom
