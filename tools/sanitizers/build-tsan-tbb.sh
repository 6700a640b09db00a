#!/usr/bin/env bash
# oneTBB built with -fsanitize=thread, for `make test-tsan` (docs/reliability.md). Debian's
# libtbb12 is not instrumented: its scheduler's synchronisation (a task's end before
# task_group::wait returns, a task's start after run) is invisible to ThreadSanitizer, which then
# reports every result a TBB task writes and the caller reads after wait() as a data race (the
# first TSan run: AcquireWholeBodyPaths, PathShortcut). The fix oneTBB documents is to build it
# with TBB_SANITIZE=thread: this script fetches the source of the installed libtbb-dev's version
# from Debian's archive (dpkg-source -x checks it against the .dsc's checksums and applies
# Debian's patches), builds the library (no tests, no tbbmalloc) and installs it in
# PREFIX (default build-tsan/third_party/tbb-tsan). Idempotent: nothing is done when PREFIX
# already holds that version. The TSan build finds it through TBB_DIR (Makefile, test-tsan).
#   tools/sanitizers/build-tsan-tbb.sh [PREFIX]
set -euo pipefail

prefix=$(realpath -m "${1:-build-tsan/third_party/tbb-tsan}")
version=$(dpkg-query -W -f='${Version}' libtbb-dev 2>/dev/null || true)
[[ -n "$version" ]] || { echo "build-tsan-tbb: libtbb-dev is not installed (make deps)" >&2; exit 1; }
stamp="$prefix/.debian-version"
if [[ -f "$stamp" && "$(cat "$stamp")" == "$version" ]]; then exit 0; fi

source_package=$(dpkg-query -W -f='${source:Package}' libtbb-dev)
upstream=${version%-*}
upstream=${upstream#*:}
pool="http://deb.debian.org/debian/pool/main/${source_package:0:1}/$source_package"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "build-tsan-tbb: oneTBB $version with -fsanitize=thread -> $prefix"
dsc="${source_package}_${version#*:}.dsc"
curl -sSf -o "$work/$dsc" "$pool/$dsc" ||
  { echo "build-tsan-tbb: cannot fetch $pool/$dsc" >&2; exit 1; }
# The files the .dsc lists (the upstream tarball, Debian's changes), from the same pool.
for file in $(awk '/^Files:/{f=1;next} /^[^ ]/{f=0} f{print $3}' "$work/$dsc"); do
  curl -sSf -o "$work/$file" "$pool/$file" || { echo "build-tsan-tbb: cannot fetch $pool/$file" >&2; exit 1; }
done
# dpkg-source checks each file against the .dsc's checksums (its signature only when a Debian
# keyring is installed: a warning otherwise; the .dsc comes from the archive the packages do).
(cd "$work" && dpkg-source -x "$dsc" src 2>&1 | grep -v "^dpkg-source: info" >&2 || true)
[[ -f "$work/src/CMakeLists.txt" ]] || { echo "build-tsan-tbb: unpacking $dsc failed" >&2; exit 1; }
cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTBB_SANITIZE=thread \
  -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF -DTBBMALLOC_BUILD=OFF \
  -DCMAKE_INSTALL_PREFIX="$prefix" >"$work/configure.log" ||
  { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/build" -j "$(nproc)" >"$work/build.log" || { tail -50 "$work/build.log" >&2; exit 1; }
cmake --install "$work/build" >/dev/null
echo "$version" >"$stamp"
echo "build-tsan-tbb: installed ($upstream)"
