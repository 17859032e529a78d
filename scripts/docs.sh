#!/usr/bin/env bash
# Regenerates the figures the README and the tutorial quote (the output blocks under their
# commands, the tutorial's card count and machine time) and the pictures in docs/images/ from
# the binary: the docs test runs every documented command in a scratch folder and, with
# PARSONS_UPDATE_DOCS=1, writes what it got instead of comparing. Review the diff, then commit.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh >/dev/null
PARSONS_UPDATE_DOCS=1 build/tests/parsons_tests "[docs]"
git status --short README.md docs/
