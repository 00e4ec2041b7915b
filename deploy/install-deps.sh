#!/usr/bin/env bash
# Installs everything socsim needs to build, run and test, from Debian 12 packages only.
# Usage: bash deploy/install-deps.sh [--with-browser]   (root, or sudo available)
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
packages=(
  build-essential cmake ninja-build pkg-config git curl python3
  libcpp-httplib-dev nlohmann-json3-dev libcurl4-openssl-dev libeigen3-dev
  libsqlite3-dev sqlite3 libpq-dev libyaml-cpp-dev libgtest-dev libgmock-dev libgeos-dev
  libboost-dev libexpected-dev libssl-dev zlib1g-dev clang-format ccache
  libzstd-dev  # MCAP chunk compression (core/interop/mcap_writer)
  libxml2-utils  # xmllint: the shell e2e tests check XML exports
  wordnet-base wordnet-dev  # prompt understanding: WordNet 3.0 data in /usr/share/wordnet and libwordnet
  clang-14 libclang-rt-14-dev  # the sanitizer + libFuzzer build (presets asan and fuzz)
)
if [ "${1:-}" = "--with-browser" ]; then
  # Test-only: Chromium for the viewer tests, nginx for the reverse-proxy fault tests.
  # PostgreSQL's server: the store, catalogue, jobs and API tests run against a scratch cluster
  # too (tests/pg/postgres.sh); the daemon itself only needs libpq.
  packages+=(chromium nginx postgresql)
  # Node.js for the browser tests; a machine that already has node (e.g. from NodeSource) keeps it.
  command -v node >/dev/null 2>&1 || packages+=(nodejs)
  command -v npm >/dev/null 2>&1 || packages+=(npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "socsim: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
