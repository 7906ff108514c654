// libFuzzer harness: `[initial] from_file` (read_initial_file, then the placement, the method's
// start checks and the report, as `carom check` does) on damaged carom files.
//
// The input does not hold the file's bytes but a list of edits to a valid run file or checkpoint
// (written at start-up by running tests/fuzz/tiny_run.toml): overwrite an element of a dataset
// or attribute with arbitrary bytes (NaN, infinities, wild indices), give a dataset another
// shape (rank 0 to 3, each extent 0 to 64) and contents, delete a dataset or an attribute,
// replace a string attribute (the file's kind, the stored scene text). The edited file is
// structurally valid HDF5, so what is tested is carom's own reading layer: shapes, types,
// ranges, missing parts and the stored scene. (Arbitrary bytes reach HDF5's own parser first;
// fuzz_initial_file_bytes.cpp does that, see tests/fuzz/README.md for what it found.)
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <string>

#include "tests/fuzz/fuzz_h5_edit.hpp"
#include "tests/fuzz/fuzz_initial_support.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  carom::fuzz::initial_file_seeds();  // runs the tiny scene once
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const carom::fuzz::InitialFileSeeds& seeds = carom::fuzz::initial_file_seeds();
  FuzzedDataProvider input(data, size);
  const bool checkpoint = input.ConsumeBool();
  const std::int64_t snapshot = input.ConsumeIntegralInRange<std::int64_t>(-4, 3);
  const bool snapshot_given = !checkpoint && input.ConsumeBool();
  const std::string path = seeds.work_dir + "/input.h5";
  carom::fuzz::write_edited(checkpoint ? seeds.checkpoint : seeds.run, path, input, 6);
  carom::fuzz::read_like_carom(path, snapshot, snapshot_given);
  return 0;
}
