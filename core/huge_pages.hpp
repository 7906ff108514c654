#pragma once
/// Arrays that the kernel may back with 2 MiB pages: the per-particle records, cell lists and
/// calendar of the event-driven engine. In a system of a million particles they fill 500 MB,
/// each event touches lines of a dozen arrays at places far apart, and with 4 KiB pages nearly
/// every such line also misses the TLB (a page walk, itself of loads that miss, and on a
/// virtual machine a walk of two page tables). Blocks of at least 2 MiB are therefore aligned
/// to 2 MiB and marked MADV_HUGEPAGE before their first use, so that where transparent huge
/// pages are "madvise" (as on the machines carom is measured on) or "always" the kernel backs
/// them with huge pages.
/// Smaller blocks (every array of a system of up to about 30 000 particles) are plain
/// allocations. Nothing computed depends on it: only where the bytes lie.
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace carom {

/// The allocator of BigVector (see above). Stateless: all instances are equal.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  /// Blocks of at least this many bytes are aligned to it and advised to use huge pages.
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;

  HugePageAllocator() noexcept = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return std::allocator<T>{}.allocate(n);
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (p == nullptr) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: where it fails, the pages stay small
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePage)
      std::allocator<T>{}.deallocate(p, n);
    else
      std::free(p);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

/// A std::vector whose large buffers may lie in huge pages (see above).
template <class T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace carom
