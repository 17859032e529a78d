#!/usr/bin/env bash
# Regenerates the figures the README and the tutorial quote (the output blocks under their
# commands, the tutorial's card count and machine time) and the pictures in docs/images/ from
# the binary and the exhibit page: the docs test runs every documented command in a scratch folder and, with
# PARSONS_UPDATE_DOCS=1, writes what it got instead of comparing. Review the diff, then commit.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh >/dev/null
PARSONS_UPDATE_DOCS=1 build/tests/parsons_tests "[docs]"
# The demo's index page as a visitor first sees it (docs/install.md), in headless Chromium at a
# laptop's width. A screenshot is not byte for byte the same on two machines (fonts), so no test
# compares it: look at it.
shot=$(mktemp -d)
trap 'rm -rf "$shot"' EXIT
(cd "$shot" && "$OLDPWD/build/cli/parsons" demo >/dev/null)
chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars --window-size=1366,1100 \
    --screenshot="$PWD/docs/images/demo-index.png" "file://$shot/out/demo/index.html" 2>/dev/null
# The exhibit page's pictures (docs/web.md): the screenshots its browser test keeps, at a
# laptop's 1366 x 768 and a phone's 390 x 844, copied under the names the page shows.
scripts/build-web.sh
node tests/js/browser_test.js build-wasm/site build/cli/parsons build-wasm/browser-test >/dev/null
for pair in first-view-laptop:web-first-view first-view-phone:web-phone tour-laptop:web-tour \
            part-info-laptop:web-part-info error-field-laptop:web-error-field \
            mill-start:web-mill-start mill-mid:web-mill-mid mill-phone:web-mill-phone mill-phone-start:web-mill-phone-start \
            tour-phone-one-screen:web-tour-phone error-words-laptop:web-error-words \
            voice-plain-laptop:web-voice reader-live-page:web-reader reader-phone:web-reader-phone \
            circuit-travel:web-circuit-travel circuit-phone:web-circuit-phone \
            circuit-tour:web-circuit-tour circuit-tour-phone:web-circuit-tour-phone; do
    cp "build-wasm/browser-test/${pair%%:*}.png" "docs/images/${pair##*:}.png"
done
git status --short README.md docs/
