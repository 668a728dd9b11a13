#!/usr/bin/env bash
# Quick start (2): set up, build everything (program, tests, benchmarks, man page), and run the
# whole test suite, the Python package's and the install's tests included.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
cd build
ctest --output-on-failure --parallel "$(nproc)" --timeout 900
