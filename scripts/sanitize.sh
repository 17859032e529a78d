#!/usr/bin/env bash
# Builds parsons, its test suite and the fuzz targets with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (the `sanitize` CMake preset, in build-sanitize/) and runs the
# suite there. See docs/testing.md.
#
#   scripts/sanitize.sh         build, then run the suite
#   scripts/sanitize.sh build   build only (scripts/test.sh builds beside the other tests)
#   scripts/sanitize.sh test    run the suite of the build there is
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-all}
case "$what" in
all | build | test) ;;
*)
    echo "usage: scripts/sanitize.sh [build|test]" >&2
    exit 2
    ;;
esac
jobs="$(nproc 2>/dev/null || echo 2)"
if [ "$what" != test ]; then
    cmake --preset sanitize >/dev/null
    cmake --build --preset sanitize --parallel "$jobs"
fi
if [ "$what" != build ]; then
    ctest --preset sanitize --parallel "$jobs"
fi
