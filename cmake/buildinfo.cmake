# Build identification reported by `socsim version` and GET /api/v1/info.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                OUTPUT_VARIABLE SOCSIM_GIT_SHA OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT SOCSIM_GIT_SHA)
  set(SOCSIM_GIT_SHA "unknown")
endif()
set(SOCSIM_BUILD_FLAVOR "${CMAKE_BUILD_TYPE}")
if(SOCSIM_SANITIZE)
  string(APPEND SOCSIM_BUILD_FLAVOR "+asan+ubsan")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/buildinfo.hpp.in ${PROJECT_BINARY_DIR}/generated/socsim/buildinfo.hpp @ONLY)
