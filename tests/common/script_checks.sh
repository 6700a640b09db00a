# Sourced by the shell tests of the repository's scripts (tests/fuzz/run_fuzzers_test.sh,
# tests/tools/sanitizers/check_child_reports_test.sh): a scratch folder removed on exit, a
# failure counter, and the summary that sets the exit status.

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0

# fail <what>: one failed check, said on stderr.
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# finish <test name>: exits 1 if a check failed, else 0.
finish() {
  if [ "$failures" -gt 0 ]; then
    echo "$1: $failures check(s) failed" >&2
    exit 1
  fi
  echo "$1: every check passed"
  exit 0
}
