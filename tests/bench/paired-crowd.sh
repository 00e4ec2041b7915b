#!/usr/bin/env bash
# Two builds of socsim-bench stepping the crowd benchmark in turns (A's step, B's step, A's, ...)
# in two processes, so both see the same machine at the same moments; prints the median and the
# quartiles of B's step time over A's, step by step, and whether both ended in the same state.
#   tests/bench/paired-crowd.sh A/socsim-bench B/socsim-bench [steps] [threads] [extra options]
# e.g. tests/bench/paired-crowd.sh /tmp/before/socsim-bench build/release/tests/bench/socsim-bench 200 1
# (docs/PERFORMANCE.md, "Paired runs"). One thread each is the steadiest; with two, each side's
# idle worker waits actively for up to 1 ms after its step, in the other's time.
set -euo pipefail
a=$1
b=$2
steps=${3:-200}
threads=${4:-1}
shift $(($# < 4 ? $# : 4))
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkfifo "$dir/a" "$dir/b"
common=(crowd --agents 10000 --steps "$steps" --threads "$threads" --walls --groups --reference-agents 0 "$@")
# Both on the same processors (with one thread, the same one): virtual processors of one machine
# can differ in speed.
cpus=$(seq -s, 0 $((threads - 1)))
taskset -c "$cpus" "$a" "${common[@]}" --turns "$dir/a,$dir/b" >"$dir/a.json" &
pid_a=$!
taskset -c "$cpus" "$b" "${common[@]}" --turns "$dir/b,$dir/a" >"$dir/b.json" &
pid_b=$!
printf 'x' >"$dir/a"  # A's first turn (a reader-writer open of the pipe does not block)
# A side that fails would leave the other waiting for its turn forever: stop both.
if ! wait -n "$pid_a" "$pid_b"; then
  kill "$pid_a" "$pid_b" 2>/dev/null || true
  echo "paired-crowd.sh: a run failed" >&2
  exit 1
fi
wait "$pid_a" "$pid_b"
python3 - "$dir/a.json" "$dir/b.json" <<'PY'
import json, statistics, sys
a, b = (json.loads(open(p).readline()) for p in sys.argv[1:3])
ratios = sorted(y / x for x, y in zip(a["step_ms"], b["step_ms"]))
q = statistics.quantiles(ratios, n=4)
print(json.dumps({"bench": "crowd-paired", "steps": len(ratios), "threads": a["threads"],
                  "a_ms_per_step": a["ms_per_step"], "b_ms_per_step": b["ms_per_step"],
                  "b_over_a_median": q[1], "b_over_a_quartiles": [q[0], q[2]],
                  "same_state": a["state_fnv1a"] == b["state_fnv1a"]}))
PY
