#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: a Debug build (preset ci: the dev build
# with line tables only), then the same suite under AddressSanitizer + UndefinedBehaviorSanitizer.
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
phase "done"
command -v ccache >/dev/null && ccache -s | grep -E 'Hits|Misses' || true
