#!/usr/bin/env bash
# Runs a test command against the scratch PostgreSQL server of SOCSIM_TEST_POSTGRES, with
# SOCSIM_TEST_BACKEND=postgres; exits 77 (CTest: skipped) when there is none, e.g. a developer's
# `ctest --preset dev` without tests/run-all.sh around it.
if [[ -z "${SOCSIM_TEST_POSTGRES:-}" ]]; then
  echo "skipped: SOCSIM_TEST_POSTGRES is not set (tests/run-all.sh starts a scratch PostgreSQL server)"
  exit 77
fi
SOCSIM_TEST_BACKEND=postgres exec "$@"
