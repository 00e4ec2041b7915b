#pragma once
// Storage for the crowd step's large per-agent arrays on transparent huge pages: a step streams
// several MiB through some 20 arrays, and on 4 KiB pages that is over a thousand TLB entries a
// pass (expensive in a virtual machine, where each miss walks two page tables).
#include <cstddef>
#include <new>
#include <vector>

namespace socsim::crowd {

// Blocks of at least kLargeBytes are mapped on their own, 2 MiB aligned and rounded up to 2 MiB,
// and advised for huge pages (MADV_HUGEPAGE: the kernel uses them when it can, under
// /sys/kernel/mm/transparent_hugepage "madvise" or "always"); smaller ones come from operator new.
// Placement only: the values stored, and so every result, are the same either way.
inline constexpr std::size_t kLargeBytes = std::size_t{256} << 10;
inline constexpr std::size_t kHugePage = std::size_t{2} << 20;
[[nodiscard]] void* large_allocate(std::size_t bytes, std::size_t alignment);
void large_deallocate(void* p, std::size_t bytes, std::size_t alignment) noexcept;

template <class T>
struct LargePageAllocator {
  using value_type = T;
  LargePageAllocator() = default;
  template <class U>
  LargePageAllocator(const LargePageAllocator<U>&) noexcept {}  // NOLINT: rebinding converts implicitly
  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(large_allocate(n * sizeof(T), alignof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { large_deallocate(p, n * sizeof(T), alignof(T)); }
  template <class U>
  bool operator==(const LargePageAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using LargeVector = std::vector<T, LargePageAllocator<T>>;

}  // namespace socsim::crowd
