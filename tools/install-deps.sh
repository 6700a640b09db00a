#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, only those missing. Idempotent and quiet
# when everything is there. Called by `make deps` (and so by `make test` and `make demo`).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache
  libeigen3-dev
  liblcm-dev liblcm-bin liblcm-java libglib2.0-dev default-jdk-headless
  iproute2 util-linux python3 can-utils
  nftables  # topay-faults (make faults): LCM datagram loss inside the graph's namespace
  liburdfdom-dev libyaml-cpp-dev nlohmann-json3-dev
  libcli11-dev libspdlog-dev libcairo2-dev libtbb-dev libceres-dev
  googletest libgtest-dev libbenchmark-dev
  libpcl-dev liboctomap-dev zlib1g-dev
  libboost-dev chromium
  qemu-system-x86 busybox-static cpio
)

# `make fuzz` (install-deps.sh --fuzz): clang with libFuzzer and the sanitizer runtimes.
if [[ "${1:-}" == "--fuzz" ]]; then
  packages+=(clang libclang-rt-14-dev)
fi

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
# The guest kernel for the real-SocketCAN tests (tools/guest/vcan-guest.sh; docs/can.md): fetched
# once into the user's cache. Not fatal: without it those tests report themselves skipped.
prepare_guest() {
  "$(dirname "$0")/guest/vcan-guest.sh" prepare ||
    echo "install-deps: no guest kernel; the real-SocketCAN tests will be skipped" >&2
}

# The viewer's page (web/): Node.js and npm (Debian's, unless a newer one is already there), then
# the npm packages exactly as each package-lock.json pins them, when the lockfile changed.
command -v npm >/dev/null || missing+=(nodejs npm)
# Also the MCAP test's reader (@mcap/core, tests/procs/log_info/mcap_js/).
prepare_web() {
  local root dir stamp
  root="$(cd "$(dirname "$0")/.." && pwd)"
  for dir in web tests/procs/log_info/mcap_js; do
    stamp="$root/$dir/node_modules/.package-lock.json"
    [[ -f "$root/$dir/package-lock.json" ]] || continue
    if [[ ! -f "$stamp" || "$root/$dir/package-lock.json" -nt "$stamp" ]]; then
      echo "install-deps: npm ci in $dir/"
      (cd "$root/$dir" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
    fi
  done
}

if [[ ${#missing[@]} -eq 0 ]]; then
  prepare_web
  prepare_guest
  exit 0
fi

sudo=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
prepare_web
prepare_guest
echo "install-deps: done"
