#!/usr/bin/env bash
# ctest bench.crowd_paired: paired-crowd.sh with one build against itself on a small crowd — the
# two processes take all their turns (no deadlock: ctest's timeout fails it), end in the same state,
# and the step-by-step ratio is a ratio of real step times.
set -euo pipefail
bench=$1
out=$(bash "$(dirname "$0")/paired-crowd.sh" "$bench" "$bench" 30 1 --agents 1000)
echo "$out"
python3 - "$out" <<'PY'
import json, sys
r = json.loads(sys.argv[1])
assert r["steps"] == 30, r
assert r["same_state"] is True, r
assert r["a_ms_per_step"] > 0 and r["b_ms_per_step"] > 0, r
assert 0.2 < r["b_over_a_median"] < 5.0, r
PY
