#!/usr/bin/env bash
# Runs the libFuzzer targets of a TOPAY_FUZZ build (make fuzz; docs/reliability.md): each for
# RUNS executions or MAX_SECONDS, whichever comes first, from its committed seeds
# (tests/fuzz/corpus/<target>/) and regressions plus what earlier runs found
# (BUILD_DIR/fuzz/corpus/<target>/, where new inputs go). A crash, a leak, a UBSan report, a
# hang (> 10 s for one input) or memory above 2.5 GB stops that target and fails the run; the
# input is kept as BUILD_DIR/fuzz/artifacts/<target>-crash-... (add it to
# tests/fuzz/regressions/<target>/ with the fix). Writes BUILD_DIR/fuzz/report.md: executions,
# time and result per target. FUZZ_JOBS (default 1) targets run at a time. FUZZ_WORKERS (default
# 1) libFuzzer processes run each target side by side, each for its share of RUNS, on the same
# corpus directories (libFuzzer reloads the first one every second, so each sees what the others
# found); the row adds their executions up and fails when any of them fails.
#
#   tools/fuzz/run_fuzzers.sh BUILD_DIR RUNS MAX_SECONDS [TARGET...]
set -uo pipefail

if [ $# -lt 3 ]; then
  echo "usage: $0 BUILD_DIR RUNS MAX_SECONDS [TARGET...]" >&2
  exit 2
fi
build_dir=$(cd "$1" && pwd)
runs=$2
max_seconds=$3
shift 3
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$build_dir/fuzz
mkdir -p "$out/artifacts" "$out/logs"

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for exe in "$build_dir"/bin/fuzz/*_fuzz; do targets+=("$(basename "$exe" _fuzz)"); done
fi
if [ ${#targets[@]} -eq 0 ]; then
  echo "run_fuzzers: no fuzz target in $build_dir/bin/fuzz (build target topay_fuzz_all)" >&2
  exit 1
fi

# One row per target in $out/rows/ (a later run of a target replaces its row); the report is
# all rows, so runs of different targets with different budgets add up to one table.
mkdir -p "$out/rows"
jobs=${FUZZ_JOBS:-1}

run_one() {
  local name=$1
  local exe=$build_dir/bin/fuzz/${name}_fuzz
  local row=$out/rows/$name.md
  if [ ! -x "$exe" ]; then
    echo "run_fuzzers: $exe is not built" >&2
    printf '| %s | - | - | - | - | - | FAILED (not built) |\n' "$name" > "$row"
    return 1
  fi
  local work=$out/corpus/$name
  mkdir -p "$work"
  local dirs=("$work" "$root/tests/fuzz/corpus/$name")
  [ -d "$root/tests/fuzz/regressions/$name" ] && dirs+=("$root/tests/fuzz/regressions/$name")
  local workers=${FUZZ_WORKERS:-1}
  local share=$(( (runs + workers - 1) / workers ))
  echo "run_fuzzers: $name (up to $runs runs, $max_seconds s, $workers worker(s))"
  local start code seconds execs rss corpus result rate w failed_log=""
  local logs=() wpids=()
  start=$(date +%s.%N)
  for ((w = 0; w < workers; ++w)); do
    local log=$out/logs/$name.log
    [ "$workers" -gt 1 ] && log=$out/logs/$name.worker$w.log
    logs+=("$log")
    ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0} \
    UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
      "$exe" -runs="$share" -max_total_time="$max_seconds" -timeout=10 -rss_limit_mb=2560 \
        -print_final_stats=1 -artifact_prefix="$out/artifacts/$name-" "${dirs[@]}" > "$log" 2>&1 &
    wpids+=($!)
  done
  code=0
  for w in "${!wpids[@]}"; do
    wait "${wpids[$w]}" || { code=$?; failed_log=${logs[$w]}; }
  done
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  execs=0
  rss=0
  for log in "${logs[@]}"; do
    local e r
    e=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    r=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -1)
    execs=$(( execs + ${e:-0} ))
    [ "${r:-0}" -gt "$rss" ] && rss=$r
  done
  corpus=$(find "$work" -type f | wc -l)
  if [ "$code" -eq 0 ]; then
    result=ok
    [ "$workers" -gt 1 ] && result="ok ($workers workers)"
  else
    result="FAILED (exit $code; $failed_log)"
    grep -m3 -E "ERROR: |runtime error|fuzz check failed|SUMMARY" "$failed_log" | sed 's/^/  /'
  fi
  rate=$(awk -v n="${execs:-0}" -v s="$seconds" 'BEGIN { printf "%.0f", (s > 0 ? n / s : 0) }')
  printf '| %s | %s | %.0f | %s | %s | %s | %s |\n' "$name" "${execs:-?}" "$seconds" "$rate" "$corpus" \
    "${rss:-?}" "$result" > "$row"
  echo "  $name: ${execs:-?} executions in ${seconds%.*} s: $result"
  [ "$code" -eq 0 ]
}

# FUZZ_JOBS targets at a time (each libFuzzer process is single-threaded).
failed=0
pids=()
for name in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || failed=1; done
  run_one "$name" &
  pids+=($!)
done
while [ "$(jobs -rp | wc -l)" -gt 0 ]; do wait -n || failed=1; done
for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done

report=$out/report.md
{
  echo "| target | executions | seconds | exec/s | corpus | peak RSS MB | result |"
  echo "|---|---:|---:|---:|---:|---:|---|"
  cat "$out"/rows/*.md
} > "$report"
grep -q FAILED "$report" && failed=1
echo "run_fuzzers: report in $report"
cat "$report"
exit $failed
