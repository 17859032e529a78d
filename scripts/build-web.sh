#!/usr/bin/env bash
# Configures and builds the WebAssembly page in build-wasm/ (cmake --preset wasm), without
# installing anything: scripts/web.sh and scripts/test.sh install first.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset wasm >/dev/null
cmake --build --preset wasm --parallel "$(nproc 2>/dev/null || echo 2)"
