#!/usr/bin/env bash
# The main job: build parsons, keypunch the bundled sample deck, read it back field by field
# and draw its cards. Everything lands in out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
mkdir -p out/demo
parsons=build/cli/parsons
$parsons punch decks/samples/patent-example.csv -o out/demo/patent-example.cbn
$parsons show out/demo/patent-example.cbn --svg out/demo/cards
echo
echo "Open out/demo/cards/card-0001.svg in a browser to see the first card."
