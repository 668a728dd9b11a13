#!/usr/bin/env bash
# Quick start (1): set up, build only the sedem program, and run the demo scene into out/demo
# (replacing the demo run already there). The tests and benchmarks are built by test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --build-only
scripts/build.sh sedem
build/app/sedem run scenes/demo.toml --out out/demo --overwrite "$@"
echo "demo: pictures in out/demo/frames/ and out/demo/figures/, ParaView series out/demo/*.pvd"
