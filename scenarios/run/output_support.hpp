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
#include "core/hdf5_arrays.hpp"
#include "scenarios/run/run_output.hpp"

namespace carom::output_detail {

constexpr const char* kRunKind = "carom run";
constexpr const char* kCheckpointKind = "carom checkpoint";

using h5::flatten;
using h5::from_row_major;
using h5::row_major;
using h5::unflatten;

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
  file.set_attribute("method", info.method);
  file.set_attribute("run_id", info.run_id);
  file.set_attribute("scene_hash", info.scene_hash());
  file.write_string("scene", info.scene_text);
}

inline RunInfo read_info(const h5::File& file, const char* kind) {
  if (!file.has_attribute("kind") || file.attribute<std::string>("kind") != kind)
    file.fail(std::string("is not a ") + kind + " file (root attribute 'kind' differs)");
  RunInfo info;
  info.seed = file.attribute<std::uint64_t>("seed");
  info.scene_name = file.attribute<std::string>("scene_name");
  info.scene_text = file.read_string("scene");
  // Files written before runs carried an identity have none: method empty, run_id 0.
  if (file.has_attribute("method")) info.method = file.attribute<std::string>("method");
  if (file.has_attribute("run_id")) info.run_id = file.attribute<std::uint64_t>("run_id");
  if (file.has_attribute("scene_hash") && file.attribute<std::uint64_t>("scene_hash") != info.scene_hash())
    file.fail("is damaged: its /scene does not match its attribute scene_hash");
  return info;
}


}  // namespace carom::output_detail
