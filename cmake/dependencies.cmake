# All dependencies come from Debian 12 packages (deploy/install-deps.sh installs them).
find_package(Threads REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(tl-expected REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(GEOS REQUIRED)
find_package(CURL REQUIRED)
find_package(SQLite3 REQUIRED)
find_package(Eigen3 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED)
find_package(ZLIB REQUIRED)
find_path(HTTPLIB_INCLUDE_DIR httplib.h REQUIRED)  # header; link httplib::httplib (below)
if(SOCSIM_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

# Debian builds cpp-httplib as a shared library with OpenSSL/zlib/brotli support; the same
# compile definitions must be used here or the class layouts differ (pkg-config carries them).
find_package(PkgConfig REQUIRED)
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
add_library(httplib::httplib ALIAS PkgConfig::HTTPLIB)
# zstd (Debian libzstd-dev): compression of MCAP chunks (core/interop/mcap_writer).
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)
add_library(zstd::zstd ALIAS PkgConfig::ZSTD)

# WordNet 3.0 (Debian wordnet-dev + wordnet-base): the open vocabulary of prompt understanding.
# The data files are read at run time from WNSEARCHDIR or /usr/share/wordnet (core/scenario/wordnet.hpp).
find_path(WORDNET_INCLUDE_DIR wn.h REQUIRED)
find_library(WORDNET_LIBRARY NAMES wordnet REQUIRED)
add_library(WordNet::WordNet UNKNOWN IMPORTED)
set_target_properties(WordNet::WordNet PROPERTIES IMPORTED_LOCATION ${WORDNET_LIBRARY}
                                                  INTERFACE_INCLUDE_DIRECTORIES ${WORDNET_INCLUDE_DIR})
