#!/usr/bin/env bash
# Builds parsons and runs the whole test suite (installing what is missing first), then the
# exhibit page's tests in a real browser (screenshots kept in build-wasm/browser-test/), then the
# same suite under AddressSanitizer and UndefinedBehaviorSanitizer (clang; the build has the
# fuzz targets too), then every fuzz target for 20 seconds. Each part alone: docs/testing.md.
set -euo pipefail
cd "$(dirname "$0")/.."
elapsed() { printf '%dm%02ds' $((SECONDS / 60)) $((SECONDS % 60)); }
scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc 2>/dev/null || echo 2)"
echo "== $(elapsed): the exhibit page: WebAssembly build (build-wasm/), tests in headless chromium"
scripts/build-web.sh
node tests/js/browser_test.js build-wasm/site build/cli/parsons build-wasm/browser-test
echo "== $(elapsed): the suite under ASan and UBSan (build-sanitize/)"
scripts/sanitize.sh
echo "== $(elapsed): the fuzz targets, 20 s each (built with the sanitizers, build-sanitize/)"
scripts/fuzz.sh 20
echo "== $(elapsed): all passed"
