#pragma once
/// A checkpoint's proof of integrity: a 64-bit checksum over every dataset and attribute of an
/// HDF5 file (names, types, shapes and stored bytes), kept in the root attribute "checksum".
/// It is written last (seal_file, after everything else) and checked first (verify_file_seal,
/// before any value is used), so a flipped bit in any stored value is refused, not resumed.
#include <cstdint>
#include <string>

#include "core/hdf5.hpp"

namespace carom {

/// Name of the root attribute that holds the checksum (left out of the checksum itself).
inline constexpr const char* kChecksumAttribute = "checksum";

/// The checksum of everything in `file` but the checksum attribute: each object's path in name
/// order, each dataset's and attribute's type, shape and bytes as stored. Any change of one
/// 64-bit word of the stored values changes it. Throws std::runtime_error on an HDF5 error.
std::uint64_t file_checksum(const h5::File& file);

/// The same 64-bit hash over a text (a scene's: RunInfo::scene_hash).
std::uint64_t text_hash(const std::string& text);

/// Writes file_checksum(file) into the root attribute "checksum" (call it last).
void seal_file(const h5::File& file);

/// Throws std::runtime_error naming the file when it has no checksum attribute or when the one
/// it has differs from file_checksum(file).
void verify_file_seal(const h5::File& file);

}  // namespace carom
