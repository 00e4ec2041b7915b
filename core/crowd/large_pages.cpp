#include "core/crowd/large_pages.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cstdint>

namespace socsim::crowd {

namespace {
std::size_t mapped_size(std::size_t bytes) {
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}
std::align_val_t small_alignment(std::size_t alignment) {
  return std::align_val_t{std::max(alignment, alignof(std::max_align_t))};
}
}  // namespace

void* large_allocate(std::size_t bytes, std::size_t alignment) {
  if (bytes < kLargeBytes) return ::operator new(bytes, small_alignment(alignment));
  const std::size_t size = mapped_size(bytes);
  // Map one huge page more than needed, then unmap the ends around a 2 MiB aligned block.
  void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  const std::uintptr_t tail = start + size + kHugePage - (aligned + size);
  if (tail > 0) munmap(reinterpret_cast<void*>(aligned + size), tail);
  void* p = reinterpret_cast<void*>(aligned);
  madvise(p, size, MADV_HUGEPAGE);  // advice only: without huge pages the block still works
  return p;
}

void large_deallocate(void* p, std::size_t bytes, std::size_t alignment) noexcept {
  if (p == nullptr) return;
  if (bytes < kLargeBytes) {
    ::operator delete(p, small_alignment(alignment));
    return;
  }
  munmap(p, mapped_size(bytes));
}

}  // namespace socsim::crowd
