#!/usr/bin/env bash
# Builds parsons in Release (build-release/) and times `parsons sweep` over a grid of CASES
# airfoil decks (default 1,000) on one core (taskset -c 0) and on every core the machine has,
# each with sweep's default --jobs (two a core it may run on), RUNS times each (default 3),
# alternately, and prints each wall time, the medians and their ratio (docs/performance.md,
# "Sweeps"). It also checks that both write the same results, byte for byte.
#
#   scripts/bench-sweep.sh [CASES] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
cases=${1:-1000}
runs=${2:-3}
scripts/install-deps.sh
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DPARSONS_BUILD_TESTS=OFF >/dev/null
cmake --build build-release -j "$(nproc 2>/dev/null || echo 2)" --target parsons >/dev/null
parsons=$PWD/build-release/cli/parsons
work=$(mktemp -d "${TMPDIR:-/tmp}/parsons-bench-sweep-XXXXXX")
trap 'rm -rf "$work"' EXIT

# The grid: NACA 2412 templates, chord 4 to 8 in, and two cutters.
grid=(airfoil --set naca=2412 --vary cutter-radius=0.125,0.25 --vary "chord=4:8:$((cases / 2))")
median() { sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
seconds() { # wall seconds of one sweep on cores $1 (a taskset list), results to $2
    local start end
    start=$(date +%s.%N)
    taskset -c "$1" "$parsons" sweep "${grid[@]}" -q -o "$2"
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { print b - a }'
}
echo "parsons sweep of $(($((cases / 2)) * 2)) decks, $runs runs each; $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2-)"
: >"$work/one" && : >"$work/two"
for ((r = 1; r <= runs; r++)); do
    s1=$(seconds 0 "$work/one.csv") && echo "$s1" >>"$work/one"
    s2=$(seconds "0-$(($(nproc) - 1))" "$work/two.csv") && echo "$s2" >>"$work/two"
    cmp -s "$work/one.csv" "$work/two.csv" || { echo "one core and $(nproc) wrote different results" >&2; exit 1; }
    printf 'run %d: one core %.2f s, %d cores %.2f s\n' "$r" "$s1" "$(nproc)" "$s2"
done
m1=$(median <"$work/one")
m2=$(median <"$work/two")
printf 'median: one core %.2f s, %d cores %.2f s: %.2f x\n' "$m1" "$(nproc)" "$m2" "$(awk -v a="$m1" -v b="$m2" 'BEGIN { print a / b }')"
