#!/usr/bin/env bash
# The CAN bridge's timing figures (docs/benchmarks.md "CAN bridge"): config/graphs/can_bench.yaml
# for DURATION seconds with the bridge's real-time settings (SCHED_FIFO 60, mlockall) and the same
# graph without them, one after the other; prints the bridge's report lines of each run.
#   tools/bench/can_bench.sh [BUILD_DIR] [DURATION_S]      (make bench-can)
set -euo pipefail
build_dir="${1:-build}"
duration_s="${2:-60}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="$root/out/can_bench"
mkdir -p "$out"
sed '/realtime: {fifo_priority/d' "$root/config/graphs/can_bench.yaml" > "$root/config/graphs/.can_bench_no_rt.yaml"
trap 'rm -f "$root/config/graphs/.can_bench_no_rt.yaml"' EXIT
for variant in rt no_rt; do
  graph="$root/config/graphs/can_bench.yaml"
  [[ $variant == no_rt ]] && graph="$root/config/graphs/.can_bench_no_rt.yaml"
  rm -rf "${out:?}/$variant"
  "$root/$build_dir/bin/topay-launch" "$graph" --run-dir "$out/$variant" \
    --duration "$duration_s" --plain > "$out/$variant.launch.txt" 2>&1 || true
  echo "== $variant ($duration_s s): $out/$variant/canbridge.log"
  grep -E "command -> CAN frame latency|cycle jitter|cycles|state:" "$out/$variant/canbridge.log" || echo "(no report)"
  grep -E "bus load" "$out/$variant/canbridge.log" | tail -1 || true
done
