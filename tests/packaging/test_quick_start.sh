#!/usr/bin/env bash
# The README's two commands: demo.sh builds only the sedem program (not the tests and
# benchmarks) and may run again over its own output; test.sh builds everything and runs ctest.
# Checked with stand-ins for cmake, ctest and sedem that record how they are called.
set -euo pipefail
src=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/repo/scripts" "$work/repo/build/app" "$work/bin"
cp "$src"/scripts/{setup.sh,build.sh,demo.sh,test.sh} "$work/repo/scripts/"
for tool in cmake ctest; do
  printf '#!/bin/sh\necho "%s $*" >> "%s/calls"\n' "$tool" "$work" > "$work/bin/$tool"
  chmod +x "$work/bin/$tool"
done
printf '#!/bin/sh\necho "sedem $*" >> "%s/calls"\n' "$work" > "$work/repo/build/app/sedem"
chmod +x "$work/repo/build/app/sedem"
# setup.sh: every package present (no apt call), as on a set-up machine.
printf '#!/bin/sh\necho "dpkg-query $*" >> "%s/calls"\necho "install ok installed"\n' "$work" \
  > "$work/bin/dpkg-query"
chmod +x "$work/bin/dpkg-query"
# ParaView unpacked already (the set-up would download and unpack its 73 MB otherwise).
mkdir -p "$work/paraview/usr/bin"
printf '#!/bin/sh\n' > "$work/paraview/usr/bin/pvpython"
chmod +x "$work/paraview/usr/bin/pvpython"
export SEDEM_PARAVIEW_DIR="$work/paraview"

fail() { echo "FAIL: $*"; echo "--- calls:"; cat "$work/calls"; exit 1; }

PATH="$work/bin:$PATH" "$work/repo/scripts/demo.sh" > /dev/null
grep -q -- "^cmake --build build .*--target sedem" "$work/calls" || fail "demo.sh: not only sedem"
[ "$(grep -c -- "^cmake --build" "$work/calls")" = 1 ] || fail "demo.sh: more than one build"
grep -q -- "^sedem run scenes/demo.toml --out out/demo --overwrite" "$work/calls" ||
  fail "demo.sh: the demo cannot run twice (no --overwrite)"
grep -q -- "^dpkg-query .* libvtk9-dev$" "$work/calls" || fail "demo.sh: no set-up"
! grep -q -- "^dpkg-query .* \(python3-pytest\|xvfb\|libgdal32\|chromium\)$" "$work/calls" ||
  fail "demo.sh: sets up the test tools or ParaView's libraries too"

: > "$work/calls"
PATH="$work/bin:$PATH" "$work/repo/scripts/test.sh" > /dev/null
build=$(grep -- "^cmake --build" "$work/calls") || fail "test.sh: no build"
case $build in *--target*) fail "test.sh: builds only some targets: $build" ;; esac
grep -q "^ctest " "$work/calls" || fail "test.sh: no ctest"
grep -q -- "^dpkg-query .* python3-pytest$" "$work/calls" || fail "test.sh: not the whole set-up"
grep -q -- "^dpkg-query .* chromium$" "$work/calls" || fail "test.sh: no Chromium for the report test"
echo "quick start: demo.sh sets up and builds sedem only and overwrites its demo; test.sh all"
