// core/huge_pages.hpp: a BigVector holds what a std::vector given the same operations holds,
// across the 2 MiB size at which its allocator changes; its large buffers start on a 2 MiB
// boundary and (where the kernel has transparent huge pages) carry the huge-page advice, which
// /proc/self/smaps shows as the flag "hg" of the mapping that holds them.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/huge_pages.hpp"

namespace carom {
namespace {

constexpr std::size_t kHuge = HugePageAllocator<char>::kHugePage;

TEST(BigVector, HoldsWhatAStdVectorHoldsAcrossTheThreshold) {
  BigVector<std::uint32_t> big;
  std::vector<std::uint32_t> plain;
  // push_back through the threshold (524 288 elements of 4 bytes), then resize, assign, copy
  // and shrink: every reallocation copies across the two kinds of blocks.
  for (std::uint32_t k = 0; k < 1'300'000; ++k) {
    big.push_back(k * 2654435761u);
    plain.push_back(k * 2654435761u);
  }
  ASSERT_TRUE(std::equal(big.begin(), big.end(), plain.begin(), plain.end()));
  big.resize(3'000'000, 7u);
  plain.resize(3'000'000, 7u);
  ASSERT_TRUE(std::equal(big.begin(), big.end(), plain.begin(), plain.end()));
  const BigVector<std::uint32_t> copy = big;
  ASSERT_TRUE(std::equal(copy.begin(), copy.end(), plain.begin(), plain.end()));
  big.assign(plain.begin(), plain.begin() + 1000);
  big.shrink_to_fit();
  ASSERT_TRUE(std::equal(big.begin(), big.end(), plain.begin(), plain.begin() + 1000));
}

TEST(BigVector, LargeBuffersStartOnAHugePage) {
  BigVector<double> large(kHuge / sizeof(double) + 1, 1.0);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kHuge, 0u);
  struct alignas(64) Record {
    double x[8];
  };
  BigVector<Record> records(100);  // small: a plain allocation, still aligned for its type
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(records.data()) % alignof(Record), 0u);
}

/// The VmFlags of the mapping of /proc/self/smaps that holds `address`, or "" if none.
std::string vm_flags_of(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> begin >> dash >> end && dash == '-' &&
        line.find(':') > line.find(' ')) {
      inside = begin <= a && a < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line + " ";
    }
  }
  return "";
}

TEST(BigVector, LargeBuffersCarryTheHugePageAdvice) {
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  BigVector<double> large(2 * kHuge / sizeof(double), 1.0);
  std::vector<double> plain(2 * kHuge / sizeof(double), 1.0);
  const std::string flags = vm_flags_of(large.data());
  ASSERT_FALSE(flags.empty()) << "no mapping in /proc/self/smaps holds the buffer";
  EXPECT_NE(flags.find(" hg "), std::string::npos) << flags;
  EXPECT_EQ(vm_flags_of(plain.data()).find(" hg "), std::string::npos)
      << "a plain vector's mapping has the advice too: the test would not see it missing";
}

}  // namespace
}  // namespace carom
