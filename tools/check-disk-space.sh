#!/usr/bin/env bash
# Usage: tools/check-disk-space.sh DIR GB
# Fails early, saying so, when the file system of DIR cannot hold a build folder of about GB
# gigabytes (what is in DIR already counts as room). A build that runs out of space part way
# fails in the linker with "No space left on device"; this names the cause before that.
set -euo pipefail
dir=$1
need_gb=$2
parent=$dir
while [[ ! -d "$parent" ]]; do parent=$(dirname "$parent"); done
free_kb=$(df -Pk "$parent" | awk 'NR == 2 { print $4 }')
have_kb=0
if [[ -d "$dir" ]]; then have_kb=$(du -sk "$dir" 2>/dev/null | cut -f1); fi
need_kb=$((need_gb * 1024 * 1024))
if (( free_kb + have_kb < need_kb )); then
  echo "error: $dir needs about ${need_gb} GB; its file system has $((free_kb / 1024 / 1024)) GB free and" \
       "$dir holds $((have_kb / 1024 / 1024)) GB. Free some space (other build folders: make clean;" \
       "the compiler cache: ccache -C) and run again." >&2
  exit 1
fi
