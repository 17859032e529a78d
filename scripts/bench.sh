#!/usr/bin/env bash
# Builds parsons in Release (build-release/) and runs the benchmark: every figure of
# docs/performance.md, median of 5 runs. Extra arguments go to `parsons bench` (e.g. --json).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DPARSONS_BUILD_TESTS=OFF >/dev/null
cmake --build build-release -j "$(nproc 2>/dev/null || echo 2)" --target parsons >/dev/null
build-release/cli/parsons bench "$@"
