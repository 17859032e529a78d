#!/usr/bin/env bash
# The main job. Builds parsons, then:
#  1. parsons demo: generates a NACA 2412 template deck (6-inch chord) by the 1952 arithmetic,
#     runs it on the emulated machine and proves the cut -> out/demo/
#  2. keypunches the hand-written sample deck, reads it back field by field, draws its cards
#     and runs it, writing its report, plot and relay trace -> out/sample/
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
parsons=build/cli/parsons
$parsons demo --out out/demo
echo
mkdir -p out/sample
$parsons punch decks/samples/patent-example.csv -o out/sample/patent-example.cbn
$parsons show out/sample/patent-example.cbn --svg out/sample/cards
$parsons run out/sample/patent-example.cbn \
    --report out/sample/report.json --plot out/sample/plot.svg \
    --trace out/sample/trace.vcd --path out/sample/path.csv
echo
echo "Open out/demo/cut.svg and out/demo/plot.svg; the sample deck's cards are in"
echo "out/sample/cards/; gtkwave out/sample/trace.vcd shows every relay."
