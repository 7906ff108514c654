#include "hdf5.hpp"

#include <algorithm>
#include <stdexcept>

namespace carom::h5 {

template <>
hid_t native_type<double>() {
  return H5T_NATIVE_DOUBLE;
}
template <>
hid_t native_type<float>() {
  return H5T_NATIVE_FLOAT;
}
template <>
hid_t native_type<std::int8_t>() {
  return H5T_NATIVE_INT8;
}
template <>
hid_t native_type<std::uint8_t>() {
  return H5T_NATIVE_UINT8;
}
template <>
hid_t native_type<std::int32_t>() {
  return H5T_NATIVE_INT32;
}
template <>
hid_t native_type<std::uint32_t>() {
  return H5T_NATIVE_UINT32;
}
template <>
hid_t native_type<std::int64_t>() {
  return H5T_NATIVE_INT64;
}
template <>
hid_t native_type<std::uint64_t>() {
  return H5T_NATIVE_UINT64;
}

namespace {

/// Turns off HDF5's printing of error stacks: errors become exceptions instead.
void silence_hdf5() {
  static const bool silenced = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)silenced;
}

/// The innermost description on HDF5's error stack (then clears the stack).
std::string hdf5_error() {
  std::string message;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* error, void* data) -> herr_t {
        auto* text = static_cast<std::string*>(data);
        if (text->empty() && error->desc) *text = error->desc;
        return 0;
      },
      &message);
  H5Eclear2(H5E_DEFAULT);
  return message;
}

/// A fixed-length UTF-8 string type of `length` bytes (at least 1), NUL-padded.
Handle string_type(std::size_t length) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<std::size_t>(length, 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

/// A simple dataspace of the given extent (scalar when dims is empty).
Handle dataspace(const std::vector<hsize_t>& dims, const std::vector<hsize_t>& max_dims = {}) {
  if (dims.empty()) return Handle(H5Screate(H5S_SCALAR), H5Sclose);
  return Handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(),
                                 max_dims.empty() ? nullptr : max_dims.data()),
                H5Sclose);
}

/// Cuts a fixed-length string buffer into its text (trailing NULs removed).
std::string trim_nuls(const char* begin, std::size_t length) {
  std::size_t end = length;
  while (end > 0 && begin[end - 1] == '\0') --end;
  return std::string(begin, end);
}

std::size_t element_count(const std::vector<hsize_t>& dims) {
  std::size_t count = 1;
  for (hsize_t d : dims) count *= d;
  return count;
}

}  // namespace

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    close_ = other.close_;
    other.id_ = -1;
  }
  return *this;
}

bool Handle::reset() {
  bool ok = true;
  if (id_ >= 0 && close_) ok = close_(id_) >= 0;
  id_ = -1;
  return ok;
}

// ---- Object ------------------------------------------------------------------------------------

void Object::fail(const std::string& what) const {
  const std::string detail = hdf5_error();
  throw std::runtime_error(file_ + ":" + path_ + ": " + what +
                           (detail.empty() ? "" : " (HDF5: " + detail + ")"));
}

std::string Object::child_path(const std::string& name) const {
  if (!name.empty() && name[0] == '/') return name;
  return path_ == "/" ? "/" + name : path_ + "/" + name;
}

void Object::write_attribute(const std::string& name, hid_t type, const std::vector<hsize_t>& dims,
                             const void* data) const {
  if (has_attribute(name) && H5Adelete(id(), name.c_str()) < 0)
    fail("cannot replace attribute '" + name + "'");
  Handle space = dataspace(dims);
  Handle attribute(H5Acreate2(id(), name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  if (!attribute.valid()) fail("cannot create attribute '" + name + "'");
  if (H5Awrite(attribute.get(), type, data) < 0) fail("cannot write attribute '" + name + "'");
}

bool Object::has_attribute(const std::string& name) const {
  const htri_t exists = H5Aexists(id(), name.c_str());
  if (exists < 0) fail("cannot look up attribute '" + name + "'");
  return exists > 0;
}

Handle Object::open_attribute(const std::string& name, hsize_t& count) const {
  if (!has_attribute(name)) fail("has no attribute '" + name + "'");
  Handle attribute(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) fail("cannot open attribute '" + name + "'");
  Handle space(H5Aget_space(attribute.get()), H5Sclose);
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points < 0) fail("cannot read the size of attribute '" + name + "'");
  count = static_cast<hsize_t>(points);
  return attribute;
}

void Object::read_attribute(const std::string& name, hid_t type, std::size_t count,
                            void* data) const {
  hsize_t stored = 0;
  Handle attribute = open_attribute(name, stored);
  if (stored != count)
    fail("attribute '" + name + "' holds " + std::to_string(stored) + " values, expected " +
         std::to_string(count));
  if (H5Aread(attribute.get(), type, data) < 0) fail("cannot read attribute '" + name + "'");
}

void Object::write_string_attribute(const std::string& name, const std::string& value) const {
  if (has_attribute(name) && H5Adelete(id(), name.c_str()) < 0)
    fail("cannot replace attribute '" + name + "'");
  Handle type = string_type(value.size());
  Handle space = dataspace({});
  Handle attribute(
      H5Acreate2(id(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid()) fail("cannot create attribute '" + name + "'");
  std::string padded = value;
  padded.resize(std::max<std::size_t>(value.size(), 1), '\0');
  if (H5Awrite(attribute.get(), type.get(), padded.data()) < 0)
    fail("cannot write attribute '" + name + "'");
}

std::string Object::read_string_attribute(const std::string& name) const {
  hsize_t count = 0;
  Handle attribute = open_attribute(name, count);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0 || count != 1)
    fail("attribute '" + name + "' is not a fixed-length string");
  const std::size_t length = H5Tget_size(type.get());
  std::string buffer(length, '\0');
  if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0)
    fail("cannot read attribute '" + name + "'");
  return trim_nuls(buffer.data(), length);
}

// ---- Dataset -----------------------------------------------------------------------------------

std::vector<hsize_t> Dataset::shape() const {
  Handle space(H5Dget_space(id()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail("cannot read the shape");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

std::size_t Dataset::size() const {
  return element_count(shape());
}

void Dataset::read_raw(hid_t type, void* data) const {
  if (size() == 0) return;
  if (H5Dread(id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) fail("cannot read");
}

void Dataset::append_raw(hid_t type, std::size_t count, const void* data) const {
  std::vector<hsize_t> dims = shape();
  if (dims.empty()) fail("is a scalar, rows cannot be appended");
  // Values per row: the product of every dimension but the first.
  const std::size_t columns = element_count({dims.begin() + 1, dims.end()});
  if (count == 0) return;
  if (columns == 0 || count % columns != 0)
    fail("cannot append " + std::to_string(count) + " values to rows of " +
         std::to_string(columns));
  const hsize_t rows = count / columns;
  std::vector<hsize_t> start(dims.size(), 0), extent = dims, block = dims;
  start[0] = dims[0];
  extent[0] = dims[0] + rows;
  block[0] = rows;
  if (H5Dset_extent(id(), extent.data()) < 0) fail("cannot grow (is it extendible?)");
  Handle file_space(H5Dget_space(id()), H5Sclose);
  if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, block.data(),
                          nullptr) < 0)
    fail("cannot select the new rows");
  Handle memory_space = dataspace(block);
  if (H5Dwrite(id(), type, memory_space.get(), file_space.get(), H5P_DEFAULT, data) < 0)
    fail("cannot write the new rows");
}

void Dataset::truncate(hsize_t rows) const {
  std::vector<hsize_t> dims = shape();
  if (dims.empty() || rows > dims[0]) fail("cannot truncate to " + std::to_string(rows) + " rows");
  dims[0] = rows;
  if (H5Dset_extent(id(), dims.data()) < 0) fail("cannot shrink (is it extendible?)");
}

std::string Dataset::read_string() const {
  Handle type(H5Dget_type(id()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0 || size() != 1)
    fail("is not a fixed-length string");
  const std::size_t length = H5Tget_size(type.get());
  std::string buffer(length, '\0');
  if (H5Dread(id(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
    fail("cannot read");
  return trim_nuls(buffer.data(), length);
}

std::vector<std::string> Dataset::read_strings() const {
  Handle type(H5Dget_type(id()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0)
    fail("is not a fixed-length string array");
  const std::size_t length = H5Tget_size(type.get());
  const std::size_t count = size();
  std::vector<char> buffer(length * count);
  std::vector<std::string> texts;
  if (count == 0) return texts;
  if (H5Dread(id(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
    fail("cannot read");
  for (std::size_t k = 0; k < count; ++k) texts.push_back(trim_nuls(&buffer[k * length], length));
  return texts;
}

// ---- Group -------------------------------------------------------------------------------------

std::string Group::describe(const std::vector<hsize_t>& shape) {
  std::string text = "{";
  for (std::size_t k = 0; k < shape.size(); ++k) text += (k ? ", " : "") + std::to_string(shape[k]);
  return text + "}";
}

Group Group::create_group(const std::string& name) const {
  Handle group(H5Gcreate2(id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid()) fail("cannot create group '" + name + "'");
  return Group(std::move(group), file_, child_path(name));
}

Group Group::open_group(const std::string& name) const {
  if (!contains(name)) fail("has no group '" + name + "'");
  Handle group(H5Gopen2(id(), name.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid()) fail("cannot open group '" + name + "'");
  return Group(std::move(group), file_, child_path(name));
}

bool Group::contains(const std::string& name) const {
  // H5Lexists needs every intermediate link to exist: check the path one step at a time.
  std::string prefix = !name.empty() && name[0] == '/' ? "/" : "";
  std::size_t begin = prefix.size();
  while (begin < name.size()) {
    const std::size_t end = std::min(name.find('/', begin), name.size());
    if (end > begin) {
      if (!prefix.empty() && prefix.back() != '/') prefix += '/';
      prefix.append(name, begin, end - begin);
      const htri_t exists = H5Lexists(id(), prefix.c_str(), H5P_DEFAULT);
      if (exists < 0) fail("cannot look up '" + prefix + "'");
      if (exists == 0) return false;
    }
    begin = end + 1;
  }
  return true;
}

std::vector<std::string> Group::children() const {
  std::vector<std::string> names;
  H5Literate(
      id(), H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->push_back(name);
        return 0;
      },
      &names);
  return names;
}

Dataset Group::open_dataset(const std::string& name) const {
  if (!contains(name)) fail("has no dataset '" + name + "'");
  Handle dataset(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) fail("cannot open dataset '" + name + "'");
  return Dataset(std::move(dataset), file_, child_path(name));
}

void Group::remove(const std::string& name) const {
  if (H5Ldelete(id(), name.c_str(), H5P_DEFAULT) < 0) fail("cannot remove '" + name + "'");
}

Dataset Group::write_raw(const std::string& name, hid_t type, const std::vector<hsize_t>& shape,
                         std::size_t count, const void* data) const {
  if (element_count(shape) != count)
    fail("dataset '" + name + "': " + std::to_string(count) + " values do not fill shape " +
         describe(shape));
  Handle space = dataspace(shape);
  Handle dataset(
      H5Dcreate2(id(), name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!dataset.valid()) fail("cannot create dataset '" + name + "'");
  if (count > 0 && H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail("cannot write dataset '" + name + "'");
  return Dataset(std::move(dataset), file_, child_path(name));
}

Dataset Group::create_extendible_raw(const std::string& name, hid_t type, std::size_t type_size,
                                     hsize_t columns) const {
  std::vector<hsize_t> dims{0}, max_dims{H5S_UNLIMITED}, chunk{0};
  // About 8 KiB per chunk: small enough for short runs, large enough for long ones.
  const hsize_t row_bytes = std::max<hsize_t>(columns, 1) * type_size;
  chunk[0] = std::max<hsize_t>(1, 8192 / row_bytes);
  if (columns > 0) {
    dims.push_back(columns);
    max_dims.push_back(columns);
    chunk.push_back(columns);
  }
  Handle space = dataspace(dims, max_dims);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data());
  Handle dataset(
      H5Dcreate2(id(), name.c_str(), type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
      H5Dclose);
  if (!dataset.valid()) fail("cannot create extendible dataset '" + name + "'");
  return Dataset(std::move(dataset), file_, child_path(name));
}

Dataset Group::write_string(const std::string& name, const std::string& text) const {
  Handle type = string_type(text.size());
  Handle space = dataspace({});
  Handle dataset(H5Dcreate2(id(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                            H5P_DEFAULT),
                 H5Dclose);
  if (!dataset.valid()) fail("cannot create dataset '" + name + "'");
  std::string padded = text;
  padded.resize(std::max<std::size_t>(text.size(), 1), '\0');
  if (H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, padded.data()) < 0)
    fail("cannot write dataset '" + name + "'");
  return Dataset(std::move(dataset), file_, child_path(name));
}

Dataset Group::write_strings(const std::string& name, const std::vector<std::string>& texts) const {
  std::size_t length = 1;
  for (const std::string& text : texts) length = std::max(length, text.size());
  std::vector<char> buffer(length * texts.size(), '\0');
  for (std::size_t k = 0; k < texts.size(); ++k)
    std::copy(texts[k].begin(), texts[k].end(), buffer.begin() + k * length);
  Handle type = string_type(length);
  Handle space = dataspace({texts.size()});
  Handle dataset(H5Dcreate2(id(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                            H5P_DEFAULT),
                 H5Dclose);
  if (!dataset.valid()) fail("cannot create dataset '" + name + "'");
  if (!texts.empty() &&
      H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
    fail("cannot write dataset '" + name + "'");
  return Dataset(std::move(dataset), file_, child_path(name));
}

// ---- File --------------------------------------------------------------------------------------

File File::create(const std::string& path) {
  silence_hdf5();
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) {
    const std::string detail = hdf5_error();
    throw std::runtime_error(path + ": cannot create the HDF5 file" +
                             (detail.empty() ? "" : " (HDF5: " + detail + ")"));
  }
  return File(std::move(file), path);
}

namespace {
/// H5Fopen with `flags` and the file-access list `access`, or an error naming the file.
Handle open_file(const std::string& path, unsigned flags, hid_t access) {
  Handle file(H5Fopen(path.c_str(), flags, access), H5Fclose);
  if (!file.valid()) {
    const std::string detail = hdf5_error();
    throw std::runtime_error(path + ": cannot open as an HDF5 file" +
                             (detail.empty() ? "" : " (HDF5: " + detail + ")"));
  }
  return file;
}
}  // namespace

File File::open(const std::string& path, bool writable) {
  silence_hdf5();
  return File(open_file(path, writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT), path);
}

File File::open_unlocked(const std::string& path) {
  silence_hdf5();
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.valid() || H5Pset_file_locking(access.get(), false, true) < 0)
    throw std::runtime_error(path + ": cannot set up an unlocked read (HDF5: " + hdf5_error() + ")");
  return File(open_file(path, H5F_ACC_RDONLY, access.get()), path);
}

void File::flush() const {
  if (H5Fflush(id(), H5F_SCOPE_GLOBAL) < 0) fail("cannot flush the file");
}

void File::close() {
  if (!handle_.reset()) fail("cannot close the file");
}

}  // namespace carom::h5
