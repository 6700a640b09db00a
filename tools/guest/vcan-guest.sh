#!/usr/bin/env bash
# A small Linux guest with a real SocketCAN `vcan0`, for the CAN tests on machines whose kernel
# has no CAN (docs/can.md, "Testing on a real SocketCAN"). QEMU (software emulation) boots
# Debian's stock kernel with an initramfs of busybox and the CAN and 9p modules; the host's root
# is shared read-only over 9p, so the guest runs the host's own binaries and libraries in a
# chroot, with vcan0 up and a private loopback multicast route (LCM stays inside the guest).
#
#   vcan-guest.sh prepare               fetch the kernel (apt-get download) and build the initramfs
#   vcan-guest.sh check                 exit 0 if a guest can be booted, else print why, exit 1
#   vcan-guest.sh run [--out DIR] [--timeout S] [--cwd DIR] -- CMD [ARG...]
#                                        boot, run CMD in the guest, print its output, exit with
#                                        CMD's exit code (124: the guest timed out, 125: it
#                                        could not start or died before CMD ended)
#
# DIR (default: a temporary folder) is shared read-write with the guest at the same path, so
# CMD can write results there (its path is in $TOPAY_GUEST_OUT in the guest). Files:
# ${TOPAY_GUEST_DIR:-$XDG_CACHE_HOME/topay-guest}.
set -euo pipefail

guest_dir="${TOPAY_GUEST_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/topay-guest}"
modules_in_load_order=(
  drivers/virtio/virtio_ring drivers/virtio/virtio drivers/virtio/virtio_pci_modern_dev
  drivers/virtio/virtio_pci_legacy_dev drivers/virtio/virtio_pci
  net/9p/9pnet net/9p/9pnet_virtio fs/netfs/netfs fs/fscache/fscache fs/9p/9p
  net/can/can net/can/can-raw net/can/can-bcm drivers/net/can/dev/can-dev drivers/net/can/vcan
)

die() { echo "vcan-guest: $*" >&2; exit 1; }

# The kernel package Debian's linux-image-amd64 points at, e.g. linux-image-6.1.0-57-amd64.
kernel_package() {
  apt-cache depends linux-image-amd64 2>/dev/null |
    sed -n 's/^ *Depends: \(linux-image-[0-9][^ ]*-amd64\)$/\1/p' | head -1
}

write_init() {
  cat > "$1" <<'INIT'
#!/bin/busybox sh
/bin/busybox --install -s /bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
for m in $(cat /modules.list); do insmod "/modules/$m.ko" || echo "vcan-guest: insmod $m failed"; done
out=$(sed -n 's/.*topay_out=\([^ ]*\).*/\1/p' /proc/cmdline)
mkdir -p /host
mount -t 9p -o trans=virtio,version=9p2000.L,ro,msize=512000 hostroot /host || echo "vcan-guest: no host root"
/bin/ip link set lo up
/bin/ip route add 224.0.0.0/4 dev lo
echo 16777216 > /proc/sys/net/core/rmem_max
/bin/ip link add dev vcan0 type vcan && /bin/ip link set up vcan0
mount -t proc proc /host/proc
mount -t sysfs sys /host/sys
mount -t devtmpfs dev /host/dev
mount -t tmpfs tmp /host/tmp
mount -t tmpfs run /host/run
mkdir -p /host/dev/shm /host/dev/pts
mount -t tmpfs shm /host/dev/shm
mkdir -p "/host$out"
mount -t 9p -o trans=virtio,version=9p2000.L,msize=512000 out "/host$out" || echo "vcan-guest: no out share"
chroot /host /bin/sh "$out/guest-command.sh" > /dev/ttyS0 2>&1
echo $? > "/host$out/guest-exit-code"
sync
poweroff -f
INIT
  chmod +x "$1"
}

prepare() {
  [[ -f "$guest_dir/vmlinuz" && -f "$guest_dir/initramfs.cpio.gz" ]] && return 0
  command -v qemu-system-x86_64 >/dev/null || die "qemu-system-x86_64 missing (apt-get install qemu-system-x86)"
  [[ -x /bin/busybox ]] || die "/bin/busybox missing (apt-get install busybox-static)"
  local package work
  package=$(kernel_package)
  [[ -n "$package" ]] || die "cannot resolve linux-image-amd64's kernel package (apt-get update?)"
  mkdir -p "$guest_dir"
  work=$(mktemp -d "$guest_dir/prepare.XXXXXX")
  (cd "$work" && apt-get download -q "$package" >/dev/null 2>&1) || die "apt-get download $package failed"
  dpkg-deb -x "$work"/"$package"_*.deb "$work/kernel"
  local modules=("$work"/kernel/lib/modules/*/kernel) root="$work/initramfs"
  mkdir -p "$root"/{bin,dev,proc,sys,modules}
  cp /bin/busybox "$root/bin/busybox"
  for m in "${modules_in_load_order[@]}"; do
    cp "${modules[0]}/$m.ko" "$root/modules/" || die "module $m not in $package"
    basename "$m" >> "$root/modules.list"
  done
  write_init "$root/init"
  (cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) > "$work/initramfs.cpio.gz"
  cp "$work"/kernel/boot/vmlinuz-* "$guest_dir/vmlinuz.tmp"
  mv "$work/initramfs.cpio.gz" "$guest_dir/initramfs.cpio.gz"
  mv "$guest_dir/vmlinuz.tmp" "$guest_dir/vmlinuz"
  echo "$package" > "$guest_dir/kernel-package"
  rm -rf "$work"
}

check() {
  command -v qemu-system-x86_64 >/dev/null || { echo "qemu-system-x86_64 not installed (make deps)"; return 1; }
  [[ -f "$guest_dir/vmlinuz" && -f "$guest_dir/initramfs.cpio.gz" ]] ||
    { echo "no guest kernel in $guest_dir (tools/guest/vcan-guest.sh prepare)"; return 1; }
  return 0
}

run() {
  local out="" timeout_s=120 cwd="$PWD"
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --out) out="$2"; shift 2 ;;
      --timeout) timeout_s="$2"; shift 2 ;;
      --cwd) cwd="$2"; shift 2 ;;
      --) shift; break ;;
      *) die "unknown option $1" ;;
    esac
  done
  [[ $# -gt 0 ]] || die "run: no command"
  local why
  why=$(check) || { echo "vcan-guest: $why" >&2; return 125; }
  [[ -n "$out" ]] || out=$(mktemp -d)
  mkdir -p "$out"
  out=$(cd "$out" && pwd -P)
  rm -f "$out/guest-exit-code"
  {
    echo "cd $(printf %q "$cwd") || exit 125"
    printf 'export PATH=%q HOME=/tmp TOPAY_IN_GUEST=1 TOPAY_GUEST_OUT=%q\n' "$PATH" "$out"
    printf '%q ' "$@"; echo
  } > "$out/guest-command.sh"
  local status=0
  timeout --kill-after=5 "$timeout_s" qemu-system-x86_64 -accel tcg -m 1024 -smp 2 -nographic -no-reboot \
    -kernel "$guest_dir/vmlinuz" -initrd "$guest_dir/initramfs.cpio.gz" \
    -append "console=ttyS0 quiet loglevel=3 panic=-1 topay_out=$out" \
    -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap \
    -virtfs "local,path=$out,mount_tag=out,security_model=none" \
    -nic none </dev/null || status=$?
  if [[ $status -eq 124 || $status -eq 137 ]]; then
    echo "vcan-guest: the guest did not finish within ${timeout_s} s" >&2; return 124
  fi
  [[ -f "$out/guest-exit-code" ]] || { echo "vcan-guest: the guest ended without running the command (qemu status $status)" >&2; return 125; }
  return "$(cat "$out/guest-exit-code")"
}

case "${1:-}" in
  prepare) prepare ;;
  check) check ;;
  run) shift; run "$@" ;;
  *) echo "usage: $0 prepare | check | run [--out DIR] [--timeout S] [--cwd DIR] -- CMD [ARG...]" >&2; exit 2 ;;
esac
