// libFuzzer harness: arbitrary bytes as the HDF5 file of `[initial] from_file`, read as
// `carom check` reads it. Seeds: the run file and checkpoint of tests/fuzz/tiny_run.toml
// (make_corpus.py). Most damaged files stop in HDF5's own parser, which is not carom's code:
// see tests/fuzz/README.md for what this found and why CI runs fuzz_initial_file instead.
#include <cstdint>
#include <fstream>
#include <string>

#include "tests/fuzz/fuzz_initial_support.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  carom::fuzz::initial_file_seeds();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = carom::fuzz::initial_file_seeds().work_dir + "/input.h5";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  carom::fuzz::read_like_carom(path, -1, false);
  return 0;
}
