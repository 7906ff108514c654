#pragma once
// Helpers shared by the run file (run_output.cpp) and checkpoints (checkpoint.cpp). Internal.
#include <fcntl.h>
#include <unistd.h>

#include <Eigen/Core>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "carom/version.hpp"
#include "core/hdf5.hpp"
#include "scenarios/run/run_output.hpp"

namespace carom::output_detail {

constexpr const char* kRunKind = "carom run";
constexpr const char* kCheckpointKind = "carom checkpoint";

inline std::vector<double> flatten(const std::vector<Vec3>& vectors) {
  std::vector<double> values;
  values.reserve(3 * vectors.size());
  for (const Vec3& v : vectors) values.insert(values.end(), {v.x(), v.y(), v.z()});
  return values;
}

inline std::vector<Vec3> unflatten(const std::vector<double>& values) {
  std::vector<Vec3> vectors(values.size() / 3);
  for (std::size_t i = 0; i < vectors.size(); ++i)
    vectors[i] = Vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
  return vectors;
}

/// A 3x3 tensor as 9 values, row by row (xx, xy, xz, yx, ...).
inline std::vector<double> row_major(const Eigen::Matrix3d& tensor) {
  std::vector<double> values(9);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) values[3 * r + c] = tensor(r, c);
  return values;
}

inline Eigen::Matrix3d from_row_major(const std::vector<double>& values) {
  Eigen::Matrix3d tensor;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) tensor(r, c) = values[3 * r + c];
  return tensor;
}

/// "run.h5" -> "run.xmf" (any other name gets ".xmf" appended).
inline std::string xdmf_path_of(const std::string& path) {
  for (const char* extension : {".h5", ".hdf5"}) {
    const std::string ext = extension;
    if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
      return path.substr(0, path.size() - ext.size()) + ".xmf";
  }
  return path + ".xmf";
}

inline std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

inline std::string snapshot_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "%06zu", index);
  return name;
}

/// Forces a file's (or a directory's) contents to disk; best effort.
inline void sync_to_disk(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

/// Replaces `path` by `temporary` in one step (POSIX rename is atomic on one file system).
inline void replace_file(const std::string& temporary, const std::string& path) {
  sync_to_disk(temporary);
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    throw std::runtime_error(path + ": cannot replace it by " + temporary + ": " +
                             std::strerror(errno));
  const std::size_t slash = path.find_last_of('/');
  sync_to_disk(slash == std::string::npos ? "." : path.substr(0, slash + 1));
}

inline void write_info(const h5::File& file, const RunInfo& info, const char* kind) {
  file.set_attribute("kind", kind);
  file.set_attribute("carom_version", kVersion);
  file.set_attribute("seed", info.seed);
  file.set_attribute("scene_name", info.scene_name);
  file.write_string("scene", info.scene_text);
}

inline RunInfo read_info(const h5::File& file, const char* kind) {
  if (!file.has_attribute("kind") || file.attribute<std::string>("kind") != kind)
    file.fail(std::string("is not a ") + kind + " file (root attribute 'kind' differs)");
  RunInfo info;
  info.seed = file.attribute<std::uint64_t>("seed");
  info.scene_name = file.attribute<std::string>("scene_name");
  info.scene_text = file.read_string("scene");
  return info;
}


}  // namespace carom::output_detail
