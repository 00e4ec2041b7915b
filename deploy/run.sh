#!/usr/bin/env bash
# Installs what is needed, builds the release binary and starts the daemon on its embedded
# defaults: SQLite file ./var/socsim.db, offline generator, HTTP :8080, WebSocket :8081.
# Extra arguments go to `socsim serve` (e.g. --host 0.0.0.0).
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
cmake --preset release -DSOCSIM_BUILD_TESTS=OFF >/dev/null
cmake --build --preset release -j "$(nproc 2>/dev/null || echo 2)" --target socsim
mkdir -p var
exec ./build/release/server/socsim serve --db ./var/socsim.db --web-root ./web "$@"
