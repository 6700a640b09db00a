#!/usr/bin/env bash
# Records a short real demo log for the viewer's tests (ctest fixture web.record_demo_log):
# the closed-loop demo graph (config/graphs/demo.yaml, without its viewer) for one seed and
# ~30 s, through topay-missions, into OUT_DIR/seed-1/graph.lcmlog. Always recorded afresh.
#
#   tests/web/record_demo_log.sh BUILD_DIR OUT_DIR
#
# topay-missions -> topay-launch runs the graph in a private network namespace (LCM multicast on
# loopback only). Where one cannot be created (no root / CAP_SYS_ADMIN, no user namespaces) the
# script exits 77 with the reason: ctest reports the test skipped (SKIP_RETURN_CODE 77).
# Exit codes: 0 recorded; 1 failed; 2 usage; 77 skipped.

set -u

if [ $# -ne 2 ]; then
  echo "usage: $0 BUILD_DIR OUT_DIR" >&2
  exit 2
fi
build_dir=$1
out_dir=$2
missions=$build_dir/bin/topay-missions
log=$out_dir/seed-1/graph.lcmlog

rm -rf "$out_dir/seed-1"  # an earlier run (its log, its launcher.out) must not stand in for this one

for exe in topay-missions topay-launch topay-scenario; do
  if [ ! -x "$build_dir/bin/$exe" ]; then
    echo "record_demo_log: $build_dir/bin/$exe is not built" >&2
    exit 1
  fi
done

# The same namespace topay-launch will ask for: as root a bare network namespace, otherwise a
# user namespace with it (unshare -rn).
if command -v unshare >/dev/null; then
  if [ "$(id -u)" -eq 0 ]; then probe=(unshare --net true); else probe=(unshare --user --map-root-user --net true); fi
  if ! why=$("${probe[@]}" 2>&1); then
    echo "record_demo_log: SKIP: cannot create a private network namespace (${probe[*]}: ${why:-failed})"
    exit 77
  fi
fi

mkdir -p "$out_dir" || exit 1
echo "record_demo_log: $missions --seeds 1 --first-seed 1 --out $out_dir --timeout-s 30 --no-view --quiet"
start=$(date +%s)
"$missions" --seeds 1 --first-seed 1 --out "$out_dir" --timeout-s 30 --no-view --quiet
code=$?
echo "record_demo_log: topay-missions exited with code $code after $(( $(date +%s) - start )) s"

launcher_out=$out_dir/seed-1/launcher.out
if [ -f "$launcher_out" ] && grep -q "cannot create a private network namespace" "$launcher_out"; then
  echo "record_demo_log: SKIP: $(grep -m1 "cannot create a private network namespace" "$launcher_out")"
  exit 77
fi
# 0: the mission succeeded in time; 3: it failed or timed out (30 s is shorter than the mission).
if [ "$code" -ne 0 ] && [ "$code" -ne 3 ]; then
  echo "record_demo_log: FAILED: topay-missions exit code $code (see $out_dir/seed-1/)" >&2
  [ -f "$launcher_out" ] && tail -20 "$launcher_out" >&2
  exit 1
fi
if [ ! -s "$log" ]; then
  echo "record_demo_log: FAILED: no log at $log" >&2
  [ -f "$launcher_out" ] && tail -20 "$launcher_out" >&2
  exit 1
fi
echo "record_demo_log: recorded $log ($(stat -c %s "$log") bytes)"
