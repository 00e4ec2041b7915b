#pragma once
// Shared by the fuzz targets (tests/fuzz/fuzz_*.cpp): the bytes as text, a check that aborts
// with a message (a broken invariant is a finding, like a crash), and the small world that the
// program and behaviour-tree targets check names against.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "core/world/world.hpp"

namespace socsim::fuzz {

inline std::string_view text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

[[noreturn]] inline void broken(const char* what, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: fuzz invariant broken: %s\n", file, line, what);
  std::abort();
}

// A world with every kind of named place (zones, doors, ROIs of the kinds behaviours use,
// entities with affordances), built once from the text in fuzz_support.cpp.
const world::World& small_world();

}  // namespace socsim::fuzz

#define SOCSIM_FUZZ_CHECK(cond) \
  ((cond) ? static_cast<void>(0) : ::socsim::fuzz::broken(#cond, __FILE__, __LINE__))
