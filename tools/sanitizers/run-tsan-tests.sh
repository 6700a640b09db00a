#!/usr/bin/env bash
# Runs test binaries of a ThreadSanitizer build one after another (each binary's tests in one
# process: the threads they start are what TSan watches) and fails if any test fails or TSan
# reports anything (halt_on_error: the report ends the binary with a failure). Prints one line
# per binary (result, seconds, reports) and the report's first lines on failure.
#   tools/sanitizers/run-tsan-tests.sh BUILD_DIR TEST_BINARY...
set -uo pipefail

build_dir=$1
shift
logs="$build_dir/tsan-logs"
mkdir -p "$logs"
suppressions="$(cd "$(dirname "$0")" && pwd)/tsan.supp"  # third-party libraries only, with reasons
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$suppressions${TSAN_OPTIONS:+:$TSAN_OPTIONS}"
failed=()
for test in "$@"; do
  binary="$build_dir/bin/$test"
  [[ -x "$binary" ]] || { echo "tsan: $test: no binary $binary" >&2; failed+=("$test"); continue; }
  start=$(date +%s)
  "$binary" >"$logs/$test.log" 2>&1
  code=$?
  # gcc 12's TSan runtime cannot map its shadow memory under the kernel's widest address space
  # randomisation (vm.mmap_rnd_bits > 28): run such a binary again without randomisation.
  if ((code != 0)) && grep -q "unexpected memory mapping" "$logs/$test.log"; then
    setarch "$(uname -m)" -R "$binary" >"$logs/$test.log" 2>&1
    code=$?
  fi
  reports=$(grep -c "WARNING: ThreadSanitizer" "$logs/$test.log")
  summary=$(grep -o "PASSED.*\|FAILED TEST.*\|SKIPPED.*" "$logs/$test.log" | head -1)
  echo "tsan: $test: exit $code, $(($(date +%s) - start)) s, $reports report(s); $summary"
  if ((code != 0 || reports != 0)); then
    failed+=("$test")
    grep -m1 -A30 "WARNING: ThreadSanitizer\|Failure" "$logs/$test.log" >&2
  fi
done
if ((${#failed[@]} > 0)); then
  echo "tsan: FAILED: ${failed[*]} (logs: $logs)" >&2
  exit 1
fi
echo "tsan: $# binaries clean (logs: $logs)"
