#!/usr/bin/env bash
# Configures and builds parsons and its test suite in build/ (after installing everything the
# tests need that is missing; scripts/demo.sh builds the program alone).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARSONS_BUILD_TESTS=ON -DPARSONS_REQUIRE_JS_TESTS=ON >/dev/null
cmake --build build --parallel "$(nproc 2>/dev/null || echo 2)"
