#!/usr/bin/env bash
# Builds parsons, its test suite and the fuzz targets with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (the `sanitize` CMake preset, in build-sanitize/) and runs the
# suite there. See docs/testing.md.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc 2>/dev/null || echo 2)"
cmake --preset sanitize >/dev/null
cmake --build --preset sanitize --parallel "$jobs"
ctest --preset sanitize --parallel "$jobs"
