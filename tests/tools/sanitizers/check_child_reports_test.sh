#!/usr/bin/env bash
# Tests tools/sanitizers/check-child-reports.sh (make test-asan, make test-tsan) on scratch build
# folders: none or clean logs pass; an ASan, LeakSanitizer, TSan or UBSan report in a log deep
# under test_out fails and is named; a log that only mentions a sanitizer passes.
#
#   tests/tools/sanitizers/check_child_reports_test.sh PATH/TO/check-child-reports.sh
set -uo pipefail

script=${1:?usage: $0 PATH/TO/check-child-reports.sh}
source "$(dirname "${BASH_SOURCE[0]}")/../../common/script_checks.sh"

# expect <case> <exit status wanted> <text the output must hold> <build dir>
expect() {
  local name=$1 want=$2 text=$3 build=$4 out status
  out=$("$script" "$build" 2>&1)
  status=$?
  [[ $status -eq $want ]] || fail "$name: exit $status, wanted $want; output: $out"
  [[ $out == *"$text"* ]] || fail "$name: output lacks '$text': $out"
}

expect "no test_out" 0 "nothing to check" "$scratch/none"

clean="$scratch/clean"
mkdir -p "$clean/test_out/procs/Graph.Test/run"
printf '[info] planner: started\n[warn] built with AddressSanitizer: slower\n' > "$clean/test_out/procs/Graph.Test/run/planner.log"
expect "clean logs" 0 "no sanitizer report" "$clean"

report() {  # report <case> <line of the report>
  local build="$scratch/$1"
  mkdir -p "$build/test_out/procs/Graph.Test/run/alpha"
  echo "[info] model: started" > "$build/test_out/procs/Graph.Test/run/ok.log"
  printf '[info] model: started\n%s\n    #0 0x5 in main main.cc:56\n' "$2" > "$build/test_out/procs/Graph.Test/run/alpha/model.log"
  expect "$1" 1 "procs/Graph.Test/run/alpha/model.log" "$build"
  local out
  out=$("$script" "$build" 2>&1)
  [[ $out == *"1 file(s)"* ]] || fail "$1: the clean log was counted: $out"
  [[ $out == *"main.cc:56"* ]] || fail "$1: the report's lines are not shown: $out"
}
report asan "==19923==ERROR: AddressSanitizer: stack-use-after-scope on address 0x7ffde5445fa0"
report lsan "==7==ERROR: LeakSanitizer: detected memory leaks"
report tsan "WARNING: ThreadSanitizer: data race (pid=12)"
report ubsan "core/a.cc:12:5: runtime error: signed integer overflow"

finish check_child_reports_test
