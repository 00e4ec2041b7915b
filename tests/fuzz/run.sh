#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (preset fuzz: build/fuzz, only the modules they link)
# and runs each in turn for the given time on its seed corpus and dictionary, under ASan + UBSan.
#   tests/fuzz/run.sh [seconds-per-target] [target...]     (default: 10 s, every target)
# FUZZ_JOBS: build parallelism (default 1). FUZZ_FLAGS: more libFuzzer flags (e.g. -jobs, -seed).
# FUZZ_BUILD=build/asan runs the executables of preset asan (coverage only in the readers; built
# by `cmake --build --preset asan`) instead of building preset fuzz.
# New inputs go to <build>/fuzz-corpus/<target> (tests/fuzz/corpus holds the seeds and is only read);
# crashes, leaks, timeouts and OOMs to <build>/fuzz-artifacts/<target>/, each run's log to
# <build>/fuzz-logs/<target>.log. Exits 1 when a target found something. (A slow-unit-* file is
# not a finding: a unit that hangs is a timeout-* after -timeout; a stopped process leaves one.)
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-10}
shift || true
targets=("$@")
if ((${#targets[@]} == 0)); then
  # The one list of targets is in tests/fuzz/CMakeLists.txt.
  read -r -a targets < <(sed -n 's/^set(socsim_fuzz_targets \(.*\))$/\1/p' tests/fuzz/CMakeLists.txt)
fi

started=$SECONDS
build=${FUZZ_BUILD:-build/fuzz}
if [[ $build == build/fuzz ]]; then
  cmake --preset fuzz >/dev/null
  cmake --build --preset fuzz -j "${FUZZ_JOBS:-1}" | grep -v '^\[\|^ninja: no work to do' || true
fi
test -x "$build/tests/fuzz/fuzz_${targets[0]}" || { echo "no fuzz executables in $build" >&2; exit 1; }
echo "fuzz build ($build): $((SECONDS - started)) s"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
final_stat() { sed -n "s/^stat::$2: *//p" "$1" | tail -1; }
count_findings() {
  find "$1" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l
}
found=0
printf '%-14s %10s %8s %6s %7s %8s %7s  %s\n' target execs exec/s cov ft corpus findings result
for t in "${targets[@]}"; do
  exe=$build/tests/fuzz/fuzz_$t
  work=$build/fuzz-corpus/$t
  artifacts=$build/fuzz-artifacts/$t
  log=$build/fuzz-logs/$t.log
  mkdir -p "$work" "$artifacts" "$(dirname "$log")"
  dict=()
  [[ -f tests/fuzz/$t.dict ]] && dict=(-dict="tests/fuzz/$t.dict")
  before=$(count_findings "$artifacts")
  rc=0
  # shellcheck disable=SC2086 # FUZZ_FLAGS is a list of flags
  "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "${dict[@]}" ${FUZZ_FLAGS:-} "$work" "tests/fuzz/corpus/$t" >"$log" 2>&1 || rc=$?
  last=$(grep -E '^#[0-9]+.*cov: ' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9]*[a-zA-Z]*\).*/\1/p' <<<"$last")
  findings=$(($(count_findings "$artifacts") - before))
  result=ok
  if ((rc != 0 || findings > 0)); then
    result="FAILED (exit $rc; see $log)"
    found=1
  fi
  printf '%-14s %10s %8s %6s %7s %8s %7s  %s\n' "$t" "$(final_stat "$log" number_of_executed_units)" \
    "$(final_stat "$log" average_exec_per_sec)" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$findings" "$result"
done
echo "fuzzing: ${#targets[@]} targets × ${seconds} s, $((SECONDS - started)) s in all"
exit "$found"
