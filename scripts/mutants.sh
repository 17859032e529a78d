#!/usr/bin/env bash
# Hand mutations, made one at a time: each block of tests/mutants/mutants.txt changes one line of
# the source the way a tired colleague might (a comparison flipped, an off-by-one, a check
# dropped), rebuilds build/ and runs the test named for it, which must now fail. The source is
# put back after each, and on any exit. See docs/testing.md.
#
#   scripts/mutants.sh                 every mutant
#   scripts/mutants.sh 'Tape*'         the mutants whose test matches this shell pattern
#
# Not part of CI (each mutant is a rebuild); run it when a rule or its test changes.
set -euo pipefail
cd "$(dirname "$0")/.."

manifest=tests/mutants/mutants.txt
only=${1:-*}
build=build
[ -d "$build" ] || scripts/build.sh

saved=""
original=""
restore() {
    if [ -n "$saved" ]; then
        cat "$saved" >"$original" # a new mtime: make rebuilds what the mutant built
        rm -f "$saved"
        saved=""
    fi
}
trap restore EXIT
trap 'restore; exit 130' INT TERM

# Replaces the one occurrence of $2 by $3 in file $1; fails if $2 is not there exactly once.
mutate() {
    FROM=$2 TO=$3 perl -0pi -e '
        BEGIN { $n = 0 }
        $n = () = /\Q$ENV{FROM}\E/g;
        s/\Q$ENV{FROM}\E/$ENV{TO}/ if $n == 1;
        END { exit($n == 1 ? 0 : 1) }' "$1"
}

caught=0
survived=()
broken=()
run_block() {
    local rule=$1 file=$2 from=$3 to=$4 test=$5
    # shellcheck disable=SC2053 # a pattern, on purpose
    [[ $test == $only ]] || return 0
    original=$file
    saved=$(mktemp)
    cat "$file" >"$saved"
    if ! mutate "$file" "$from" "$to"; then
        broken+=("$rule: the text is not in $file exactly once")
        restore
        return 0
    fi
    printf '%-70.70s ' "$rule"
    if ! cmake --build "$build" --target parsons parsons_tests --parallel 2 >/tmp/mutant-build.log 2>&1; then
        echo "does not build (see /tmp/mutant-build.log)"
        broken+=("$rule: does not build")
    elif "$build/tests/parsons_tests" "$test" >/tmp/mutant-test.log 2>&1; then
        echo "SURVIVED"
        survived+=("$rule ($test)")
    else
        echo "caught"
        caught=$((caught + 1))
    fi
    restore
}

rule="" file="" from="" to="" test=""
while IFS= read -r line || [ -n "$line" ]; do
    case $line in
    "#"*) ;;
    rule:*) rule=${line#rule: } ;;
    file:*) file=${line#file: } ;;
    from:*) from=${line#from: } ;;
    to:*) to=${line#to: } ;;
    test:*)
        test=${line#test: }
        run_block "$rule" "$file" "$from" "$to" "$test"
        rule="" file="" from="" to="" test=""
        ;;
    esac
done <"$manifest"

cmake --build "$build" --target parsons parsons_tests --parallel 2 >/dev/null
echo "$caught caught, ${#survived[@]} survived, ${#broken[@]} not applied"
for s in "${survived[@]}" "${broken[@]}"; do
    echo "  $s"
done
[ ${#survived[@]} -eq 0 ] && [ ${#broken[@]} -eq 0 ]
