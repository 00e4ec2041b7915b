# Project-wide warnings and sanitizers, applied through one interface target.
add_library(socsim_options INTERFACE)
target_compile_options(socsim_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                                -Wold-style-cast -Wcast-align)
# GCC 12 at -O2/-O3 reports std::string copies as overlapping memcpy (GCC bug 105329) and, with
# the sanitizers, std::regex internals as maybe-uninitialized (GCC bug 105562): false positives in
# the standard library that would turn optimised builds red under -Werror.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(socsim_options INTERFACE -Wno-restrict -Wno-maybe-uninitialized)
endif()
# A unity batch (the CI presets) includes .cpp files, and GCC then takes a class that derives
# from or holds a type of a file's anonymous namespace for one declared in a header.
if(CMAKE_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(socsim_options INTERFACE -Wno-subobject-linkage)
endif()
if(SOCSIM_WERROR)
  target_compile_options(socsim_options INTERFACE -Werror)
endif()
# SOCSIM_FUZZ implies the sanitizers: a libFuzzer target without them finds only crashes.
# The sanitizers check the code under test: the test and benchmark executables' own sources
# (targets with the property SOCSIM_TEST_CODE: socsim_test(), socsim-bench) are compiled at -O0
# without instrumentation, which halves the sanitizer build (docs/PERFORMANCE.md, "CI time"); they
# still link the sanitizer runtimes and the instrumented libraries. The fuzz harnesses stay
# instrumented.
if(SOCSIM_SANITIZE OR SOCSIM_FUZZ)
  set(instrumented "$<NOT:$<BOOL:$<TARGET_PROPERTY:SOCSIM_TEST_CODE>>>")
  target_compile_options(socsim_options INTERFACE
    "$<${instrumented}:-fsanitize=address,undefined;-fno-sanitize-recover=undefined>"
    "$<$<NOT:${instrumented}>:-O0>" -fno-omit-frame-pointer)
  target_link_options(socsim_options INTERFACE -fsanitize=address,undefined)
endif()
if(SOCSIM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SOCSIM_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++-14 or cmake --preset fuzz")
  endif()
  # Coverage instrumentation: with the suite (preset asan) only for the readers the targets
  # exercise (tests/fuzz/CMakeLists.txt, socsim_fuzz_covered), so the simulation and generator code
  # the heavy tests spend their time in runs uninstrumented; alone (preset fuzz) for everything.
  if(NOT SOCSIM_BUILD_TESTS)
    target_compile_options(socsim_options INTERFACE -fsanitize=fuzzer-no-link)
  endif()
endif()

# socsim_module(name SOURCES ... [PUBLIC libs...] [PRIVATE libs...]): a core library target with
# the project options. PUBLIC only for what the module's headers include (docs/ARCHITECTURE.md);
# tests/architecture checks both lists against the includes.
function(socsim_module name)
  cmake_parse_arguments(M "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${name} STATIC ${M_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC socsim_options ${M_PUBLIC} PRIVATE ${M_PRIVATE})
endfunction()
