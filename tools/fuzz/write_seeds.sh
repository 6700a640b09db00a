#!/usr/bin/env bash
# Regenerates the committed seed corpora of the fuzz targets (tests/fuzz/corpus/<target>/):
# the LCM targets' from a real graph log (LOG, or 30 s of the demo recorded afresh with
# tests/web/record_demo_log.sh, which needs a private network namespace), the CAN targets'
# from the drivers' own encoders, the loaders' from the shipped config files.
#
#   tools/fuzz/write_seeds.sh BUILD_DIR [LOG]      (BUILD_DIR: a `make build-test` build)
set -euo pipefail

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 BUILD_DIR [LOG]" >&2
  exit 2
fi
build_dir=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
corpus=$root/tests/fuzz/corpus

log=${2:-}
if [ -z "$log" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  "$root/tests/web/record_demo_log.sh" "$build_dir" "$tmp"
  log=$tmp/seed-1/graph.lcmlog
fi

cmake --build "$build_dir" --target write_lcm_fuzz_seeds write_can_fuzz_seeds >/dev/null
for target in lcm_decode estimator_inputs tracker_inputs mission_inputs director_inputs planner_intake \
              viz_inputs map_update trajectory_message sim_inputs mapper_inputs motorsim_inputs; do
  rm -rf "${corpus:?}/$target"
done
"$build_dir/bin/write_lcm_fuzz_seeds" "$log" "$corpus"
"$build_dir/bin/write_can_fuzz_seeds" "$corpus"
"$root/tools/fuzz/write_loader_seeds.sh" "$build_dir"
