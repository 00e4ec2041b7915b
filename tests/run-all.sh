#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test, in two phases:
# - preset ci: GCC Debug build (line tables only); every test except those labelled heavy.
# - preset asan: clang 14, -O1, ASan + UBSan (LeakSanitizer on, every UBSan report fatal), with
#   SOCSIM_FUZZ: the whole suite including the heavy tests (the slow generator and property sweeps,
#   CTest label heavy, socsim_test HEAVY in tests/CMakeLists.txt: run once, here, where -O1 makes
#   them 2-3x faster), and each libFuzzer target replaying its seeds (fuzz_replay.<target>) then
#   fuzzing for SOCSIM_FUZZ_SECONDS (default 10; fuzz.<target>). So every test runs in one phase or
#   both, and CI builds with both compilers.
# tests/fuzz/run.sh is for longer local libFuzzer runs (preset fuzz, build/fuzz).
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
for preset in ci asan; do
  phase "${preset}: configure and build"
  if [[ $preset == asan ]]; then
    cmake --preset "$preset" -DSOCSIM_FUZZ_SECONDS="${SOCSIM_FUZZ_SECONDS:-10}" >/dev/null
  else
    cmake --preset "$preset" >/dev/null
  fi
  cmake --build --preset "$preset" -j "$jobs"
  phase "${preset}: test"
  ctest --preset "$preset" -j "$jobs"
done
phase "done"
command -v ccache >/dev/null && ccache -s | grep -E 'Hits|Misses' || true
