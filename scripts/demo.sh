#!/usr/bin/env bash
# The main job: build parsons, keypunch the bundled sample deck, read it back field by field,
# draw its cards, then run it through the emulated cabinet and write the report, the plot,
# the relay trace (open it in GTKWave) and the path. Everything lands in out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
mkdir -p out/demo
parsons=build/cli/parsons
$parsons punch decks/samples/patent-example.csv -o out/demo/patent-example.cbn
$parsons show out/demo/patent-example.cbn --svg out/demo/cards
echo
$parsons run out/demo/patent-example.cbn \
    --report out/demo/report.json --plot out/demo/plot.svg \
    --trace out/demo/trace.vcd --path out/demo/path.csv
echo
echo "Cards:  out/demo/cards/card-0001.svg .. (open in a browser)"
echo "Run:    out/demo/plot.svg, out/demo/report.json"
echo "Relays: gtkwave out/demo/trace.vcd"
