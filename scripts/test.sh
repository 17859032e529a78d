#!/usr/bin/env bash
# Builds parsons and runs the whole test suite (installing what is missing first).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc 2>/dev/null || echo 2)"
