#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: a Debug build (preset ci: the dev build
# with line tables only) runs every test except those labelled heavy (the slow generator and
# property sweeps: socsim_test HEAVY in tests/CMakeLists.txt), then the whole suite, heavy tests
# included, runs under AddressSanitizer + UndefinedBehaviorSanitizer (preset asan, -O1: 2-3x
# faster than Debug there), so every test runs in one phase or both;
# with SOCSIM_FUZZ_SECONDS set, then every libFuzzer target for that long (tests/fuzz/run.sh).
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
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  phase "${preset}: test"
  ctest --preset "$preset" -j "$jobs"
done
# Both presets above replay every fuzz target's corpus (CTest label fuzz). Running libFuzzer itself
# is opt-in: its clang build costs about 11.5 CPU-minutes from a cold ccache (docs/RELIABILITY.md,
# Fuzzing), more than CI's budget. SOCSIM_FUZZ_SECONDS=10 runs each target 10 s under ASan + UBSan.
if [[ -n "${SOCSIM_FUZZ_SECONDS:-}" ]]; then
  phase "fuzz: clang build and ${SOCSIM_FUZZ_SECONDS} s per target"
  FUZZ_JOBS=$jobs bash tests/fuzz/run.sh "$SOCSIM_FUZZ_SECONDS"
fi
phase "done"
command -v ccache >/dev/null && ccache -s | grep -E 'Hits|Misses' || true
