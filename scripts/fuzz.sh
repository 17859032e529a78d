#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/; the `fuzz` CMake preset is the `sanitize` one:
# clang, ASan, UBSan, in build-sanitize/) and runs each for a fixed time, two at a time, starting from its seed corpus
# (tests/fuzz/corpus/TARGET/) and every kept regression input (tests/fuzz/regressions/TARGET/).
# New interesting inputs collect in build-sanitize/corpus/TARGET/; a crash, a hang or a leak is
# written to build-sanitize/findings/TARGET/ and the script fails. See docs/testing.md.
#
#   scripts/fuzz.sh                  every target for 20 s
#   scripts/fuzz.sh 300              every target for five minutes
#   scripts/fuzz.sh 60 machine text  those two for a minute each
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-20}
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
    for dir in tests/fuzz/corpus/*/; do
        targets+=("$(basename "$dir")")
    done
fi
jobs=${PARSONS_FUZZ_JOBS:-2}
build=build-sanitize

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --parallel "$(nproc 2>/dev/null || echo 2)"

# One target: its log, its final statistics and its exit code go to build-sanitize/logs/.
run_one() {
    local t=$1
    mkdir -p "$build/corpus/$t" "$build/findings/$t" "$build/logs"
    local inputs=("$build/corpus/$t" "tests/fuzz/corpus/$t")
    if [ -d "tests/fuzz/regressions/$t" ]; then
        inputs+=("tests/fuzz/regressions/$t")
    fi
    local flags=()
    if [ -f "tests/fuzz/$t.dict" ]; then
        flags+=("-dict=tests/fuzz/$t.dict")
    fi
    if [ -f "tests/fuzz/$t.options" ]; then # more libFuzzer flags for this target, one line
        read -r -a options <"tests/fuzz/$t.options"
        flags+=("${options[@]}")
    fi
    local rc=0
    "$build/tests/fuzz/fuzz_$t" "${inputs[@]}" "${flags[@]}" -max_total_time="$seconds" \
        -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$build/findings/$t/" >"$build/logs/$t.log" 2>&1 || rc=$?
    echo "$rc" >"$build/logs/$t.rc"
}

echo "fuzzing ${targets[*]}: ${seconds} s each, ${jobs} at a time"
for t in "${targets[@]}"; do
    if [ ! -x "$build/tests/fuzz/fuzz_$t" ]; then
        echo "no fuzz target '$t' (the targets are the folders of tests/fuzz/corpus/)" >&2
        exit 2
    fi
    rm -f "$build/logs/$t.rc"
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do
        wait -n || true
    done
    run_one "$t" &
done
wait

failed=()
for t in "${targets[@]}"; do
    log="$build/logs/$t.log"
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    corpus=$(ls "$build/corpus/$t" | wc -l)
    rc=$(cat "$build/logs/$t.rc" 2>/dev/null || echo "?")
    if [ "$rc" = 0 ]; then
        printf '  %-8s ok: %s runs in %s s, %s inputs in its corpus\n' "$t" "${runs:-?}" \
            "$seconds" "$corpus"
    else
        printf '  %-8s FINDING (exit %s), log %s:\n' "$t" "$rc" "$log"
        grep -E "ERROR|SUMMARY|what\(\)|Test unit written|==[0-9]+==" "$log" | head -20 | sed 's/^/      /'
        failed+=("$t")
    fi
done
if [ ${#failed[@]} -ne 0 ]; then
    echo "fuzz findings in: ${failed[*]} (inputs in $build/findings/; keep each, once fixed," \
        "in tests/fuzz/regressions/TARGET/)" >&2
    exit 1
fi
