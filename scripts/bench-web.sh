#!/usr/bin/env bash
# The exhibit page's benchmark (tests/js/browser_bench.js): the demo deck "to the end" in
# headless chromium against the native Release build, the first view, the wasm size; medians of 5.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DPARSONS_BUILD_TESTS=OFF >/dev/null
cmake --build build-release -j "$(nproc 2>/dev/null || echo 2)" --target parsons >/dev/null
scripts/build-web.sh >/dev/null
node tests/js/browser_bench.js build-wasm/site build-release/cli/parsons build-wasm/bench "${1:-5}"
# The recorded run against the plain one, the module alone in node (tests/js/record_bench.js).
rm -rf build-wasm/bench-deck && build-release/cli/parsons demo --out build-wasm/bench-deck >/dev/null
node tests/js/record_bench.js build-wasm/site build-wasm/bench-deck/airfoil-template/naca2412.cbn
