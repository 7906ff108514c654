#pragma once
/// The edits the file harnesses (fuzz_initial_file.cpp, fuzz_resume.cpp) make to a valid carom
/// HDF5 file: overwrite an element of a dataset or attribute with arbitrary bytes (NaN,
/// infinities, wild indices), give a dataset another shape (rank 0 to 3, each extent 0 to 64)
/// and contents, delete a dataset or an attribute, replace a string attribute (the file's kind,
/// the stored scene text). The edited file stays structurally valid HDF5.
#include <fuzzer/FuzzedDataProvider.h>

#include <string>

#include "tests/fuzz/fuzz_initial_support.hpp"

namespace carom::fuzz {

/// Writes a copy of `seed` at `path` with up to `max_edits` edits read from `input` (the count
/// first, then per edit its kind, target and values). CAROM_FUZZ_VERBOSE=1 prints the edits.
void write_edited(const SeedFile& seed, const std::string& path, FuzzedDataProvider& input,
                  int max_edits);

}  // namespace carom::fuzz
