// `carom info --tree`: the raw HDF5 tree of a file (every group and dataset, attributes).
#include "scenarios/cli/info.hpp"

#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/hdf5.hpp"

namespace carom {

namespace {

struct WalkState {
  std::ostream* out;
  std::size_t groups = 0, datasets = 0;
  std::size_t snapshots = 0;          ///< Groups directly under /snapshots.
  std::string first_snapshot;         ///< Only this snapshot's contents are listed.
  double first_time = 0, last_time = 0;
};

/// The `time` attribute of a group, or NaN.
double time_attribute(hid_t group) {
  double time = NAN;
  if (H5Aexists(group, "time") > 0) {
    const hid_t attribute = H5Aopen(group, "time", H5P_DEFAULT);
    H5Aread(attribute, H5T_NATIVE_DOUBLE, &time);
    H5Aclose(attribute);
  }
  return time;
}

/// Text of a scalar or short 1-D attribute (numbers or strings).
std::string attribute_text(hid_t attribute) {
  const hid_t type = H5Aget_type(attribute);
  const hid_t space = H5Aget_space(attribute);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::string text;
  const H5T_class_t kind = H5Tget_class(type);
  if (kind == H5T_STRING) {
    if (H5Tis_variable_str(type) > 0) {
      char* value = nullptr;
      const hid_t memory = H5Tcopy(H5T_C_S1);
      H5Tset_size(memory, H5T_VARIABLE);
      if (n == 1 && H5Aread(attribute, memory, &value) >= 0 && value) {
        text = value;
        H5free_memory(value);
      }
      H5Tclose(memory);
    } else {
      std::vector<char> buffer(H5Tget_size(type) * static_cast<std::size_t>(std::max<hssize_t>(n, 1)) + 1, '\0');
      if (H5Aread(attribute, type, buffer.data()) >= 0) text = buffer.data();
    }
    text = std::string(1, '"').append(text).append(1, '"');
  } else if ((kind == H5T_INTEGER || kind == H5T_FLOAT) && n >= 1 && n <= 16) {
    std::vector<double> values(static_cast<std::size_t>(n));
    if (H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data()) >= 0) {
      for (hssize_t i = 0; i < n; ++i) {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), "%.10g", values[static_cast<std::size_t>(i)]);
        text += (i ? ", " : "") + std::string(buffer);
      }
      if (n > 1) text = std::string(1, '[').append(text).append(1, ']');
    }
  } else {
    std::ostringstream count;
    count << '(' << n << " values)";
    text = count.str();
  }
  H5Sclose(space);
  H5Tclose(type);
  return text;
}

herr_t print_attribute(hid_t location, const char* name, const H5A_info_t*, void* data) {
  auto* state = static_cast<WalkState*>(data);
  const hid_t attribute = H5Aopen(location, name, H5P_DEFAULT);
  if (attribute < 0) return 0;
  *state->out << "    @" << name << " = " << attribute_text(attribute) << "\n";
  H5Aclose(attribute);
  return 0;
}

herr_t visit_object(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto* state = static_cast<WalkState*>(data);
  std::ostream& out = *state->out;
  const std::string path = name;
  if (path == ".") return 0;
  // Snapshots: list the first one in full, then only count them and their times.
  if (path.rfind("snapshots/", 0) == 0) {
    const std::string rest = path.substr(10);
    const std::string group = rest.substr(0, rest.find('/'));
    if (rest.find('/') == std::string::npos && info->type == H5O_TYPE_GROUP) {
      const hid_t g = H5Gopen2(root, name, H5P_DEFAULT);
      const double t = g >= 0 ? time_attribute(g) : NAN;
      if (g >= 0) H5Gclose(g);
      if (state->snapshots++ == 0) {
        state->first_snapshot = group;
        state->first_time = t;
      }
      state->last_time = t;
    }
    if (group != state->first_snapshot) return 0;
  }
  if (info->type == H5O_TYPE_GROUP) {
    ++state->groups;
    out << "  /" << name << "/\n";
    const hid_t group = H5Gopen2(root, name, H5P_DEFAULT);
    if (group >= 0) {
      hsize_t index = 0;
      H5Aiterate2(group, H5_INDEX_NAME, H5_ITER_INC, &index, print_attribute, data);
      H5Gclose(group);
    }
  } else if (info->type == H5O_TYPE_DATASET) {
    ++state->datasets;
    const hid_t dataset = H5Dopen2(root, name, H5P_DEFAULT);
    if (dataset < 0) return 0;
    const hid_t space = H5Dget_space(dataset);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
    if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    out << "  /" << name << "  ";
    if (rank == 0) out << "scalar";
    for (int k = 0; k < rank; ++k) out << (k ? " x " : "") << dims[static_cast<std::size_t>(k)];
    out << "\n";
    hsize_t index = 0;
    H5Aiterate2(dataset, H5_INDEX_NAME, H5_ITER_INC, &index, print_attribute, data);
    H5Sclose(space);
    H5Dclose(dataset);
  }
  return 0;
}

}  // namespace

void print_file_tree(const std::string& path, std::ostream& out) {
  require_hdf5_file(path);
  // Unlocked, as carom info: a run still being written is read as of its last flush.
  const h5::File opened = h5::File::open_unlocked(path);
  const hid_t file = opened.id();
  WalkState state;
  state.out = &out;
  out << path << " (" << std::filesystem::file_size(path) << " bytes)\n";
  hsize_t index = 0;
  H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_INC, &index, print_attribute, &state);
  const herr_t status = H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, visit_object, &state, H5O_INFO_BASIC);
  if (status < 0) throw std::runtime_error(path + ": cannot read the file's structure");
  if (state.snapshots > 1)
    out << "  (" << state.snapshots - 1 << " more snapshots like /snapshots/" << state.first_snapshot << ")\n";
  if (state.snapshots > 0)
    out << state.snapshots << " snapshots from t = " << state.first_time << " s to t = " << state.last_time << " s\n";
  out << state.groups << " groups, " << state.datasets << " datasets\n";
}

}  // namespace carom
