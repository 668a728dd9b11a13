#!/usr/bin/env bash
# Configures and builds sedem (Release) in build/: every target, or only those named
# (scripts/build.sh sedem). With CI set, warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
werror=OFF
[[ -n "${CI:-}" ]] && werror=ON
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSEDEM_WERROR="$werror" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build --parallel "$(nproc)" ${targets[@]+"${targets[@]}"}
