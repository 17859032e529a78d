#!/usr/bin/env bash
# Builds parsons and runs the whole test suite (installing what is missing first), then the
# exhibit page's tests in a real browser (screenshots kept in build-wasm/browser-test/), then the
# same suite under AddressSanitizer and UndefinedBehaviorSanitizer (clang; the build has the
# fuzz targets too), then every fuzz target for 20 seconds. Each part alone: docs/testing.md.
#
# The sanitizers' build starts as soon as the regular one is done, at the lowest priority, beside
# the regular suite, the WebAssembly build and the browser tests: it takes the cycles they leave
# (a long test running alone, the page's link, the browser on one core) and no more; its output
# goes to build-sanitize/build.log and is shown when it is waited for.
set -euo pipefail
cd "$(dirname "$0")/.."
elapsed() { printf '%dm%02ds' $((SECONDS / 60)) $((SECONDS % 60)); }
scripts/build.sh
mkdir -p build-sanitize
# A session of its own (setsid), so that a failure of the rest stops the whole build with it.
setsid -w nice -n 19 scripts/sanitize.sh build >build-sanitize/build.log 2>&1 &
sanitize_build=$!
trap 'kill -- "-$sanitize_build" 2>/dev/null || true' EXIT
echo "== $(elapsed): the suite (build/); the sanitizers' build begins beside it, at the lowest priority"
ctest --test-dir build --output-on-failure --parallel "$(nproc 2>/dev/null || echo 2)"
echo "== $(elapsed): the exhibit page: WebAssembly build (build-wasm/), tests in headless chromium"
scripts/build-web.sh
node tests/js/browser_test.js build-wasm/site build/cli/parsons build-wasm/browser-test
echo "== $(elapsed): the sanitizers' build (build-sanitize/build.log)"
build_rc=0
wait "$sanitize_build" || build_rc=$?
cat build-sanitize/build.log
if [ "$build_rc" -ne 0 ]; then
    echo "the sanitizers' build failed (exit $build_rc): build-sanitize/build.log" >&2
    exit "$build_rc"
fi
echo "== $(elapsed): the suite under ASan and UBSan (build-sanitize/)"
scripts/sanitize.sh test
echo "== $(elapsed): the fuzz targets, 20 s each (built with the sanitizers, build-sanitize/)"
scripts/fuzz.sh 20
echo "== $(elapsed): all passed"
