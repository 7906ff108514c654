#pragma once
/// A thin RAII layer over the HDF5 C API: files, groups, datasets and attributes whose handles
/// close themselves, typed helpers for 1-D and 2-D arrays, strings and extendible (appendable)
/// datasets. Every failure becomes a std::runtime_error that names the file, the object path
/// and HDF5's own description of what went wrong.
///
/// Numbers are stored in the machine's native types (H5T_NATIVE_DOUBLE, ...), so a double
/// written and read back is the same bit pattern. Strings are fixed-length UTF-8, padded with
/// NULs (h5py reads them as bytes; `.decode()` gives the text).
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace carom::h5 {

/// The HDF5 memory type of a C++ number type (double, float, (u)int8/32/64).
template <class T>
hid_t native_type();

/// Owns one HDF5 identifier and closes it with the matching H5*close function.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Closes now; returns false when HDF5 reported an error while closing.
  bool reset();

 private:
  hid_t id_ = -1;
  Closer close_ = nullptr;
};

/// Anything with a name in a file: the file itself, a group or a dataset. Carries the file
/// path and the object path for error messages, and reads and writes attributes.
class Object {
 public:
  hid_t id() const { return handle_.get(); }
  const std::string& file_path() const { return file_; }
  const std::string& object_path() const { return path_; }

  /// Writes (or replaces) a scalar attribute: a number or a string.
  template <class T>
  void set_attribute(const std::string& name, const T& value) const;
  /// Writes (or replaces) a 1-D numeric attribute.
  template <class T>
  void set_attribute(const std::string& name, const std::vector<T>& values) const;
  bool has_attribute(const std::string& name) const;
  /// Reads a scalar attribute (a number, converted to T, or a std::string).
  template <class T>
  T attribute(const std::string& name) const;
  /// Reads a 1-D numeric attribute.
  template <class T>
  std::vector<T> attribute_vector(const std::string& name) const;

  /// Throws std::runtime_error "file:path: what (HDF5: innermost error)".
  [[noreturn]] void fail(const std::string& what) const;

 protected:
  Object() = default;
  Object(Handle handle, std::string file, std::string path)
      : handle_(std::move(handle)), file_(std::move(file)), path_(std::move(path)) {}
  /// Path of a child called `name` of this object.
  std::string child_path(const std::string& name) const;

  Handle handle_;
  std::string file_;
  std::string path_;

 private:
  void write_attribute(const std::string& name, hid_t type, const std::vector<hsize_t>& dims,
                       const void* data) const;
  /// Opens attribute `name`; returns its number of elements.
  Handle open_attribute(const std::string& name, hsize_t& count) const;
  void read_attribute(const std::string& name, hid_t type, std::size_t count, void* data) const;
  void write_string_attribute(const std::string& name, const std::string& value) const;
  std::string read_string_attribute(const std::string& name) const;
};

/// A dataset: an n-dimensional array of numbers or strings.
class Dataset : public Object {
 public:
  Dataset(Handle handle, std::string file, std::string path)
      : Object(std::move(handle), std::move(file), std::move(path)) {}
  /// Current extent of every dimension.
  std::vector<hsize_t> shape() const;
  /// Total number of elements.
  std::size_t size() const;
  /// The whole dataset, converted to T, in row-major order.
  template <class T>
  std::vector<T> read() const {
    std::vector<T> values(size());
    read_raw(native_type<T>(), values.data());
    return values;
  }
  /// Appends rows to an extendible dataset: `values` holds whole rows, row-major.
  template <class T>
  void append(const std::vector<T>& values) const {
    append_raw(native_type<T>(), values.size(), values.data());
  }
  /// Keeps only the first `rows` rows of an extendible dataset.
  void truncate(hsize_t rows) const;
  /// A scalar (or 1-element) fixed-length string dataset.
  std::string read_string() const;
  /// A 1-D fixed-length string dataset.
  std::vector<std::string> read_strings() const;

 private:
  void read_raw(hid_t type, void* data) const;
  void append_raw(hid_t type, std::size_t count, const void* data) const;
};

/// A group (the root group when it is a File).
class Group : public Object {
 public:
  Group(Handle handle, std::string file, std::string path)
      : Object(std::move(handle), std::move(file), std::move(path)) {}

  Group create_group(const std::string& name) const;
  Group open_group(const std::string& name) const;
  /// True when a link called `name` (a relative path is fine) exists.
  bool contains(const std::string& name) const;
  /// Names of the direct children, in name order.
  std::vector<std::string> children() const;
  Dataset open_dataset(const std::string& name) const;
  /// Unlinks the child `name` (its space in the file is not reclaimed).
  void remove(const std::string& name) const;

  /// Writes a new dataset of the given shape (empty: 1-D of values.size()), row-major.
  template <class T>
  Dataset write(const std::string& name, const std::vector<T>& values,
                std::vector<hsize_t> shape = {}) const {
    if (shape.empty()) shape = {values.size()};
    return write_raw(name, native_type<T>(), shape, values.size(), values.data());
  }
  /// Reads a whole dataset, converted to T; checks its shape when `expected_shape` is given.
  template <class T>
  std::vector<T> read(const std::string& name,
                      const std::vector<hsize_t>& expected_shape = {}) const {
    Dataset data = open_dataset(name);
    if (!expected_shape.empty() && data.shape() != expected_shape)
      data.fail("has shape " + describe(data.shape()) + ", expected " + describe(expected_shape));
    return data.read<T>();
  }
  /// An empty dataset of `columns` columns (0: 1-D) whose rows are added by Dataset::append.
  template <class T>
  Dataset create_extendible(const std::string& name, hsize_t columns) const {
    return create_extendible_raw(name, native_type<T>(), sizeof(T), columns);
  }
  /// A scalar fixed-length string dataset.
  Dataset write_string(const std::string& name, const std::string& text) const;
  std::string read_string(const std::string& name) const {
    return open_dataset(name).read_string();
  }
  /// A 1-D fixed-length string dataset.
  Dataset write_strings(const std::string& name, const std::vector<std::string>& texts) const;
  std::vector<std::string> read_strings(const std::string& name) const {
    return open_dataset(name).read_strings();
  }

  /// "{2, 3}" for error messages.
  static std::string describe(const std::vector<hsize_t>& shape);

 protected:
  Group() = default;

 private:
  Dataset write_raw(const std::string& name, hid_t type, const std::vector<hsize_t>& shape,
                    std::size_t count, const void* data) const;
  Dataset create_extendible_raw(const std::string& name, hid_t type, std::size_t type_size,
                                hsize_t columns) const;
};

/// An HDF5 file; as a Group it is the root group "/".
class File : public Group {
 public:
  /// Creates (truncating) a file.
  static File create(const std::string& path);
  /// Opens an existing file, read-only or for appending.
  static File open(const std::string& path, bool writable);
  /// Opens a file read-only without HDF5's file lock, so that a file another process is writing
  /// (a run in progress) can be read: what it holds is as of that process's last flush.
  static File open_unlocked(const std::string& path);
  /// Writes everything buffered to disk (H5Fflush).
  void flush() const;
  /// Closes the file now, reporting errors (the destructor closes silently).
  void close();

 private:
  File(Handle handle, std::string path) : Group(std::move(handle), std::move(path), "/") {}
};

// ---- template definitions -------------------------------------------------------------------

template <class T>
void Object::set_attribute(const std::string& name, const T& value) const {
  if constexpr (std::is_convertible_v<const T&, std::string>) {
    write_string_attribute(name, std::string(value));
  } else {
    static_assert(std::is_arithmetic_v<T>, "attributes are numbers or strings");
    write_attribute(name, native_type<T>(), {}, &value);
  }
}

template <class T>
void Object::set_attribute(const std::string& name, const std::vector<T>& values) const {
  write_attribute(name, native_type<T>(), {values.size()}, values.data());
}

template <class T>
T Object::attribute(const std::string& name) const {
  if constexpr (std::is_same_v<T, std::string>) {
    return read_string_attribute(name);
  } else {
    T value{};
    read_attribute(name, native_type<T>(), 1, &value);
    return value;
  }
}

template <class T>
std::vector<T> Object::attribute_vector(const std::string& name) const {
  hsize_t count = 0;
  open_attribute(name, count);
  std::vector<T> values(count);
  read_attribute(name, native_type<T>(), count, values.data());
  return values;
}

}  // namespace carom::h5
