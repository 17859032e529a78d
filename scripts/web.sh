#!/usr/bin/env bash
# Builds the exhibit page (the emulator compiled to WebAssembly, web/, docs/web.md) into
# build-wasm/site and serves it on http://127.0.0.1:PORT/ (default 8052) until Ctrl-C.
#   scripts/web.sh            build and serve
#   scripts/web.sh --build    build only
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build-web.sh
if [ "${1:-}" = "--build" ]; then
    echo "parsons: the page is in build-wasm/site (serve it with any static web server)"
    exit 0
fi
port="${PORT:-8052}"
echo "parsons: the exhibit page on http://127.0.0.1:$port/ (Ctrl-C stops it)"
exec node tests/js/serve.js build-wasm/site "$port"
