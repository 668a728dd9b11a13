#!/usr/bin/env bash
# Quick start (1): set up, build, and run the default scene into out/demo.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
build/app/sedem run scenes/demo.toml --out out/demo "$@"
echo "demo: pictures in out/demo/frames/ and out/demo/figures/, ParaView series out/demo/*.pvd"
