#!/usr/bin/env bash
# Installs what is needed, builds with two compilers, and runs every test once:
# - preset ci (GCC, Debug, unity batches): the daemon and CLI with every core module, built with
#   -Wall -Wextra -Werror, so the compiler of the README's install command sees all product code;
# - preset asan (clang 14, -O1, ASan + UBSan, LeakSanitizer on, every UBSan report fatal, with
#   SOCSIM_FUZZ): the whole suite, heavy tests included (CTest label heavy, socsim_test HEAVY in
#   tests/CMakeLists.txt), the end-to-end tests against the sanitized daemon, and each libFuzzer
#   target replaying its seeds (fuzz_replay.<target>) then fuzzing for SOCSIM_FUZZ_SECONDS
#   (default 10; fuzz.<target>). Test code itself is compiled without instrumentation
#   (cmake/warnings.cmake); the code under test is instrumented.
# Developers: `cmake --preset dev && cmake --build --preset dev && ctest --preset dev` runs the
# suite without sanitizers; `ctest --preset ci` does so on the CI's GCC build.
# tests/fuzz/run.sh is for longer local libFuzzer runs (preset fuzz, build/fuzz).
# The store and API tests also run against a scratch PostgreSQL server (tests/pg/postgres.sh,
# SOCSIM_TEST_POSTGRES); without one they skip, saying so.
# Used by README and by .ci/run. Each phase prints its wall time (docs/PERFORMANCE.md, CI time).
set -euo pipefail
cd "$(dirname "$0")/.."
started=$SECONDS
phase() { echo "=== $1 (at $((SECONDS - started)) s)"; }
bash deploy/install-deps.sh --with-browser
# Browser and schema tests: playwright-core (driving Debian's chromium) and ajv, pinned by the lockfile.
(cd tests/e2e && npm ci --no-audit --no-fund --loglevel=error)

bash tests/check-format.sh

jobs=$(nproc 2>/dev/null || echo 2)
phase "ci: configure and build the daemon with GCC"
cmake --preset ci >/dev/null
cmake --build --preset ci -j "$jobs" --target socsim
phase "asan: configure and build"
cmake --preset asan -DSOCSIM_FUZZ_SECONDS="${SOCSIM_FUZZ_SECONDS:-10}" >/dev/null
cmake --build --preset asan -j "$jobs"
phase "asan: test"
# A scratch PostgreSQL server for the store tests and the pg.* entries (the API, jobs and catalogue
# tests on PostgreSQL; issue 21), stopped however the tests end.
pgdir=$(mktemp -d /tmp/socsim-pg.XXXXXX)
trap 'bash tests/pg/postgres.sh stop "$pgdir"; rm -rf "$pgdir"' EXIT
SOCSIM_TEST_POSTGRES=$(bash tests/pg/postgres.sh start "$pgdir")
export SOCSIM_TEST_POSTGRES
ctest --preset asan -j "$jobs"
phase "done"
command -v ccache >/dev/null && ccache -s | grep -E 'Hits|Misses' || true
