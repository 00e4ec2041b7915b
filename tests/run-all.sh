#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test: the normal build, then the same suite
# under AddressSanitizer + UndefinedBehaviorSanitizer. Used by README and by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh --with-browser
# Browser and schema tests: playwright-core (driving Debian's chromium) and ajv, pinned by the lockfile.
(cd tests/e2e && npm ci --no-audit --no-fund --loglevel=error)

bash tests/check-format.sh

jobs=$(nproc 2>/dev/null || echo 2)
for preset in dev asan; do
  echo "=== ${preset}: configure and build"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  echo "=== ${preset}: test"
  ctest --preset "$preset" -j "$jobs"
done
