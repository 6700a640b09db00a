#!/usr/bin/env bash
# Tests tools/fuzz/run_fuzzers.sh (make fuzz) without clang: a scratch build directory whose
# bin/fuzz/ holds stand-ins for libFuzzer binaries. Each stand-in takes a worker slot, prints
# libFuzzer's final stats for the executions it was given (-runs=N), and fails like a sanitizer
# report when its slot is FAKE_FUZZ_FAIL_SLOT. Checks the report row of one worker, of two
# workers (executions added up), of two workers of which one fails (the row and the exit status
# fail and name that worker's log), and of a target that is not built.
#
#   tests/fuzz/run_fuzzers_test.sh PATH/TO/run_fuzzers.sh
set -uo pipefail

script=${1:?usage: $0 PATH/TO/run_fuzzers.sh}
source "$(dirname "${BASH_SOURCE[0]}")/../common/script_checks.sh"

# A stand-in for a libFuzzer binary: bin/fuzz/<name>_fuzz in a scratch build directory.
make_fake_target() {
  local build=$1 name=$2
  mkdir -p "$build/bin/fuzz"
  cat > "$build/bin/fuzz/${name}_fuzz" <<'EOF'
#!/usr/bin/env bash
runs=0
for arg in "$@"; do
  case $arg in -runs=*) runs=${arg#-runs=} ;; esac
done
slot=0
until mkdir "$FAKE_FUZZ_STATE/slot$slot" 2>/dev/null; do slot=$((slot + 1)); done
if [ "$slot" = "${FAKE_FUZZ_FAIL_SLOT:-none}" ]; then
  echo "==1==ERROR: AddressSanitizer: heap-buffer-overflow (stand-in, slot $slot)"
  echo "stat::number_of_executed_units: 3"
  exit 1
fi
echo "stat::number_of_executed_units: $runs"
echo "stat::peak_rss_mb: $((40 + slot))"
EOF
  chmod +x "$build/bin/fuzz/${name}_fuzz"
}

# run_case NAME WORKERS RUNS FAIL_SLOT TARGET...: runs the script on a fresh scratch build
# directory; sets $status, $row (the report row of the first target) and $out.
run_case() {
  local case_name=$1 workers=$2 runs=$3 fail_slot=$4
  shift 4
  local build=$scratch/$case_name
  mkdir -p "$build/state"
  make_fake_target "$build" alpha
  out=$(FAKE_FUZZ_STATE=$build/state FAKE_FUZZ_FAIL_SLOT=$fail_slot FUZZ_WORKERS=$workers \
          bash "$script" "$build" "$runs" 60 "$@" 2>&1)
  status=$?
  row=$(grep "^| $1 |" "$build/fuzz/report.md" 2>/dev/null || true)
}

expect() {  # expect DESCRIPTION CONDITION...
  local what=$1
  shift
  "$@" || fail "$what (status $status; row '$row')"$'\n'"$out"
}

run_case one_worker 1 1000 none alpha
expect "one worker: exit 0" test "$status" -eq 0
expect "one worker: 1000 executions, ok" grep -qE '^\| alpha \| 1000 \| [0-9]+ \| [0-9]+ \| 0 \| 40 \| ok \|$' <<< "$row"

run_case two_workers 2 7 none alpha
expect "two workers: exit 0" test "$status" -eq 0
# 7 runs in two shares of 4: the row adds them up; the peak RSS is the larger one.
expect "two workers: 8 executions, ok (2 workers)" \
  grep -qE '^\| alpha \| 8 \| [0-9]+ \| [0-9]+ \| 0 \| 41 \| ok \(2 workers\) \|$' <<< "$row"
expect "two workers: a log per worker" \
  test -f "$scratch/two_workers/fuzz/logs/alpha.worker0.log" -a -f "$scratch/two_workers/fuzz/logs/alpha.worker1.log"

run_case one_worker_fails 2 1000 1 alpha
expect "a worker fails: the run fails" test "$status" -ne 0
expect "a worker fails: the row says FAILED with that worker's log" \
  grep -qE '^\| alpha \| 503 \| .*FAILED \(exit 1; .*/alpha\.worker[01]\.log\) \|$' <<< "$row"
expect "a worker fails: its report is shown" grep -q "AddressSanitizer: heap-buffer-overflow" <<< "$out"

run_case not_built 1 1000 none missing
expect "a target not built: the run fails" test "$status" -ne 0
expect "a target not built: its row says so" grep -qF '| missing | - | - | - | - | - | FAILED (not built) |' <<< "$row"

finish run_fuzzers_test
