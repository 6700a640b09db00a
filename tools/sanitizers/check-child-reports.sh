#!/usr/bin/env bash
# Fails when a process a test started wrote a sanitizer report into the test's output folder.
#
#   tools/sanitizers/check-child-reports.sh <build dir>
#
# A test fails on a report from its own binary (the sanitizer aborts it), but a graph test's
# processes run under topay-launch, which restarts one that dies: an ASan abort of a child is
# then a restart the test may ride out, and the report stays in that child's log under
# <build dir>/test_out. `make test-asan` and `make test-tsan` clear test_out before ctest and run
# this after it. Prints every file with a report, with the report's first lines.
set -uo pipefail
build_dir=${1:?usage: check-child-reports.sh <build dir>}
out="$build_dir/test_out"
if [[ ! -d "$out" ]]; then
  echo "check-child-reports: no $out (no test wrote output): nothing to check"
  exit 0
fi
pattern='ERROR: AddressSanitizer|ERROR: LeakSanitizer|WARNING: ThreadSanitizer|: runtime error: '
mapfile -t files < <(grep -rlE --binary-files=text "$pattern" "$out" | sort)
if [[ ${#files[@]} -eq 0 ]]; then
  echo "check-child-reports: no sanitizer report in the logs under $out"
  exit 0
fi
echo "check-child-reports: ${#files[@]} file(s) under $out hold a sanitizer report:"
for f in "${files[@]}"; do
  echo "--- ${f#"$out"/}"
  grep -m1 -A4 -E --binary-files=text "$pattern" "$f"
done
exit 1
