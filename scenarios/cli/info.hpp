#pragma once
/// `carom info FILE.h5`: what a run file or checkpoint holds, without Python.
#include <ostream>
#include <string>

namespace carom {

/// Prints the root attributes (version, seed, scene name), then every group and dataset with its
/// shape and, for groups, their attributes (snapshot times). Throws std::runtime_error when the
/// file is not a readable HDF5 file.
void print_file_info(const std::string& path, std::ostream& out);

}  // namespace carom
