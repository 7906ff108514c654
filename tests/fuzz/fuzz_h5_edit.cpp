#include "tests/fuzz/fuzz_h5_edit.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace carom::fuzz {

namespace {

/// Bytes of every element of an HDF5 dataset or attribute, read in its native memory type.
struct Elements {
  hid_t memory_type = -1;
  std::size_t element_size = 0;
  std::vector<std::uint8_t> bytes;
};

/// Replaces element k's bytes by the next ones of the input (zeros when it runs out).
void overwrite_element(Elements& e, FuzzedDataProvider& input) {
  const std::size_t count = e.element_size == 0 ? 0 : e.bytes.size() / e.element_size;
  if (count == 0) return;
  const std::size_t k = input.ConsumeIntegralInRange<std::size_t>(0, count - 1);
  std::vector<std::uint8_t> value = input.ConsumeBytes<std::uint8_t>(e.element_size);
  value.resize(e.element_size, 0);
  std::copy(value.begin(), value.end(),
            e.bytes.begin() + static_cast<std::ptrdiff_t>(k * e.element_size));
}

/// True for types whose elements are plain bytes (numbers, fixed-length strings).
bool plain(hid_t type) {
  return H5Tis_variable_str(type) <= 0 && H5Tget_class(type) != H5T_VLEN;
}

void edit_dataset_element(hid_t file, const std::string& path, FuzzedDataProvider& input) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return;
  const hid_t type = H5Dget_type(set), space = H5Dget_space(set);
  if (plain(type)) {
    Elements e;
    e.memory_type = H5Tget_native_type(type, H5T_DIR_ASCEND);
    e.element_size = H5Tget_size(e.memory_type);
    e.bytes.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) * e.element_size);
    if (!e.bytes.empty() &&
        H5Dread(set, e.memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, e.bytes.data()) >= 0) {
      overwrite_element(e, input);
      H5Dwrite(set, e.memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, e.bytes.data());
    }
    H5Tclose(e.memory_type);
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Dclose(set);
}

void reshape_dataset(hid_t file, const std::string& path, FuzzedDataProvider& input) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return;
  const hid_t type = H5Dget_type(set);
  H5Dclose(set);
  if (!plain(type) || H5Ldelete(file, path.c_str(), H5P_DEFAULT) < 0) {
    H5Tclose(type);
    return;
  }
  const int rank = input.ConsumeIntegralInRange(0, 3);
  hsize_t dims[3] = {1, 1, 1};
  hsize_t count = 1;
  for (int k = 0; k < rank; ++k) count *= dims[k] = input.ConsumeIntegralInRange<hsize_t>(0, 64);
  // At most 4 MB of contents: 64^3 elements of a long fixed-length string (a stored random
  // generator's state) would be gigabytes, and seconds of the harness's own writing.
  const std::size_t element_size = H5Tget_size(type);
  while (rank > 0 && count * element_size > (std::size_t{1} << 22)) {
    hsize_t* largest = std::max_element(dims, dims + rank);
    *largest /= 2;
    count = 1;
    for (int k = 0; k < rank; ++k) count *= dims[k];
  }
  const hid_t space = rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims, nullptr);
  const hid_t created =
      H5Dcreate2(file, path.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (created >= 0) {
    const hid_t memory_type = H5Tget_native_type(type, H5T_DIR_ASCEND);
    std::vector<std::uint8_t> bytes =
        input.ConsumeBytes<std::uint8_t>(count * H5Tget_size(memory_type));
    bytes.resize(count * H5Tget_size(memory_type), 0);
    if (count > 0) H5Dwrite(created, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
    H5Tclose(memory_type);
    H5Dclose(created);
  }
  H5Sclose(space);
  H5Tclose(type);
}

void edit_attribute(hid_t file, const carom::fuzz::AttributeName& name, FuzzedDataProvider& input,
                    bool retext) {
  const hid_t attribute =
      H5Aopen_by_name(file, name.object.c_str(), name.name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return;
  const hid_t type = H5Aget_type(attribute), space = H5Aget_space(attribute);
  const bool is_string = H5Tget_class(type) == H5T_STRING;
  if (retext && is_string) {
    // A new text of any length (the kind, the stored scene), fixed-length as carom writes it.
    H5Aclose(attribute);
    H5Adelete_by_name(file, name.object.c_str(), name.name.c_str(), H5P_DEFAULT);
    const std::string text = input.ConsumeRandomLengthString(4096);
    const hid_t text_type = H5Tcopy(H5T_C_S1);
    H5Tset_size(text_type, std::max<std::size_t>(text.size(), 1));
    H5Tset_strpad(text_type, H5T_STR_NULLPAD);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t created = H5Acreate_by_name(file, name.object.c_str(), name.name.c_str(), text_type,
                                            scalar, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<char> padded(std::max<std::size_t>(text.size(), 1), '\0');
    std::copy(text.begin(), text.end(), padded.begin());
    if (created >= 0) {
      H5Awrite(created, text_type, padded.data());
      H5Aclose(created);
    }
    H5Sclose(scalar);
    H5Tclose(text_type);
  } else if (plain(type)) {
    Elements e;
    e.memory_type = H5Tget_native_type(type, H5T_DIR_ASCEND);
    e.element_size = H5Tget_size(e.memory_type);
    e.bytes.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) * e.element_size);
    if (!e.bytes.empty() && H5Aread(attribute, e.memory_type, e.bytes.data()) >= 0) {
      overwrite_element(e, input);
      H5Awrite(attribute, e.memory_type, e.bytes.data());
    }
    H5Tclose(e.memory_type);
    H5Aclose(attribute);
  } else {
    H5Aclose(attribute);
  }
  H5Sclose(space);
  H5Tclose(type);
}

}  // namespace

void write_edited(const SeedFile& seed, const std::string& path, FuzzedDataProvider& input,
                  int max_edits) {
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(seed.bytes.data()),
              static_cast<std::streamsize>(seed.bytes.size()));
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) return;
  // CAROM_FUZZ_VERBOSE=1: print the edits an input makes (to read a crash's artifact).
  static const bool verbose = std::getenv("CAROM_FUZZ_VERBOSE") != nullptr;
  const int edits = input.ConsumeIntegralInRange(0, max_edits);
  for (int k = 0; k < edits && input.remaining_bytes() > 0; ++k) {
    const int kind = input.ConsumeIntegralInRange(0, 5);
    if (kind <= 2 && !seed.datasets.empty()) {
      const std::string& set =
          seed.datasets[input.ConsumeIntegralInRange<std::size_t>(0, seed.datasets.size() - 1)];
      if (verbose)
        std::fprintf(stderr, "edit %d: kind %d (0 element, 1 reshape, 2 delete) of %s\n", k, kind,
                     set.c_str());
      if (kind == 0) edit_dataset_element(file, set, input);
      if (kind == 1) reshape_dataset(file, set, input);
      if (kind == 2) H5Ldelete(file, set.c_str(), H5P_DEFAULT);
    } else if (kind >= 3 && !seed.attributes.empty()) {
      const auto& attribute =
          seed.attributes[input.ConsumeIntegralInRange<std::size_t>(0, seed.attributes.size() - 1)];
      if (verbose)
        std::fprintf(stderr,
                     "edit %d: kind %d (3 delete, 4 element, 5 text) of attribute %s of %s\n", k,
                     kind, attribute.name.c_str(), attribute.object.c_str());
      if (kind == 3)
        H5Adelete_by_name(file, attribute.object.c_str(), attribute.name.c_str(), H5P_DEFAULT);
      if (kind == 4) edit_attribute(file, attribute, input, false);
      if (kind == 5) edit_attribute(file, attribute, input, true);
    }
  }
  H5Fclose(file);
}

}  // namespace carom::fuzz
