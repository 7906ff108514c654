#include "scenarios/run/file_checksum.hpp"

#include <hdf5.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace carom {

namespace {

/// A 64-bit hash over a stream of 64-bit words: each word is mixed by a bijection and folded in
/// by another (xor, multiply by an odd constant, rotate), so a change of any one word always
/// changes the result. Not cryptographic: it detects damage, not tampering.
class WordHash {
 public:
  void word(std::uint64_t w) {
    w *= 0x9E3779B97F4A7C15ull;
    w ^= w >> 29;
    state_ ^= w;
    state_ *= 0xBF58476D1CE4E5B9ull;
    state_ = (state_ << 31) | (state_ >> 33);
    ++count_;
  }
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::size_t k = 0;
    for (; k + 8 <= size; k += 8) {
      std::uint64_t w;
      std::memcpy(&w, p + k, 8);
      word(w);
    }
    if (k < size) {
      std::uint64_t w = 0;
      std::memcpy(&w, p + k, size - k);
      word(w ^ (std::uint64_t(size - k) << 56));
    }
    word(size);
  }
  void text(const std::string& s) { bytes(s.data(), s.size()); }
  std::uint64_t value() const {
    std::uint64_t h = state_ ^ count_;
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    return h;
  }

 private:
  std::uint64_t state_ = 0x243F6A8885A308D3ull;
  std::uint64_t count_ = 0;
};

/// Owns an HDF5 identifier and closes it with `close`.
struct Id {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Id() {
    if (id >= 0) close(id);
  }
};

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw std::runtime_error(file + ": " + what);
}

/// Folds a type's class and size, the shape and the stored bytes of a dataset or attribute in.
void hash_values(WordHash& hash, hid_t type, hid_t space, const std::string& file, const std::string& where,
                 bool is_attribute, hid_t object) {
  if (H5Tis_variable_str(type) > 0) fail(file, where + " is a variable-length string (carom writes none)");
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) fail(file, "cannot read the shape of " + where);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  hash.word(static_cast<std::uint64_t>(H5Tget_class(type)));
  const std::size_t type_size = H5Tget_size(type);
  hash.word(type_size);
  hash.word(static_cast<std::uint64_t>(rank));
  std::size_t points = 1;
  for (hsize_t d : dims) {
    hash.word(d);
    points *= static_cast<std::size_t>(d);
  }
  if (H5Sget_simple_extent_type(space) == H5S_NULL) points = 0;
  std::vector<unsigned char> buffer(points * type_size);
  if (points > 0) {
    const herr_t read = is_attribute ? H5Aread(object, type, buffer.data())
                                     : H5Dread(object, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data());
    if (read < 0) fail(file, "cannot read " + where + " for its checksum");
  }
  hash.bytes(buffer.data(), buffer.size());
}

struct Walk {
  WordHash hash;
  std::string file;
  bool failed = false;
  std::string error;
};

void hash_attributes(Walk& walk, hid_t object, const std::string& path) {
  H5O_info_t info;
  if (H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS) < 0) fail(walk.file, "cannot list the attributes of " + path);
  for (hsize_t k = 0; k < info.num_attrs; ++k) {
    Id attribute{H5Aopen_by_idx(object, ".", H5_INDEX_NAME, H5_ITER_INC, k, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
    if (attribute.id < 0) fail(walk.file, "cannot open an attribute of " + path);
    const ssize_t length = H5Aget_name(attribute.id, 0, nullptr);
    std::string name(static_cast<std::size_t>(std::max<ssize_t>(length, 0)), '\0');
    H5Aget_name(attribute.id, name.size() + 1, name.data());
    if (path == "/" && name == kChecksumAttribute) continue;
    walk.hash.text(name);
    Id type{H5Aget_type(attribute.id), H5Tclose};
    Id space{H5Aget_space(attribute.id), H5Sclose};
    if (type.id < 0 || space.id < 0) fail(walk.file, "cannot read attribute '" + name + "' of " + path);
    hash_values(walk.hash, type.id, space.id, walk.file, "attribute '" + name + "' of " + path, true, attribute.id);
  }
}

herr_t hash_object(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto& walk = *static_cast<Walk*>(data);
  try {
    const std::string path = std::string(name) == "." ? "/" : "/" + std::string(name);
    walk.hash.text(path);
    walk.hash.word(static_cast<std::uint64_t>(info->type));
    Id object{H5Oopen(root, name, H5P_DEFAULT), H5Oclose};
    if (object.id < 0) fail(walk.file, "cannot open " + path);
    hash_attributes(walk, object.id, path);
    if (info->type == H5O_TYPE_DATASET) {
      Id type{H5Dget_type(object.id), H5Tclose};
      Id space{H5Dget_space(object.id), H5Sclose};
      if (type.id < 0 || space.id < 0) fail(walk.file, "cannot read dataset " + path);
      hash_values(walk.hash, type.id, space.id, walk.file, "dataset " + path, false, object.id);
    }
    return 0;
  } catch (const std::exception& e) {
    walk.failed = true;
    walk.error = e.what();
    return -1;
  }
}

}  // namespace

std::uint64_t file_checksum(const h5::File& file) {
  Walk walk;
  walk.file = file.file_path();
  const herr_t status = H5Ovisit2(file.id(), H5_INDEX_NAME, H5_ITER_INC, hash_object, &walk, H5O_INFO_BASIC);
  if (walk.failed) throw std::runtime_error(walk.error);
  if (status < 0) fail(walk.file, "cannot walk the file's objects for its checksum (damaged HDF5 structure)");
  return walk.hash.value();
}

std::uint64_t text_hash(const std::string& text) {
  WordHash hash;
  hash.text(text);
  return hash.value();
}

void seal_file(const h5::File& file) { file.set_attribute(kChecksumAttribute, file_checksum(file)); }

void verify_file_seal(const h5::File& file) {
  if (!file.has_attribute(kChecksumAttribute))
    file.fail("has no checksum (root attribute 'checksum'): it was written by a carom that did not seal its "
              "checkpoints, or the attribute is damaged; its values cannot be trusted");
  const auto stored = file.attribute<std::uint64_t>(kChecksumAttribute);
  const std::uint64_t computed = file_checksum(file);
  if (stored != computed)
    file.fail("is damaged: its checksum does not match its contents (a stored value changed after it was "
              "written); resume from an intact copy or run the scene again");
}

}  // namespace carom
