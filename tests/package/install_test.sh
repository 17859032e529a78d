#!/usr/bin/env bash
# The install and the .deb, as a user gets them (docs/install.md): `cmake --install` into a
# temporary prefix, whose parsons runs the demo and finds its bundled data from any folder, and
# whose CMake package builds and runs examples/; then `cpack` makes the .deb, whose contents,
# dependencies and unpacked tree are checked.
#   install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$(realpath "$1")
source=$(realpath "$2")
work=$3
rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
prefix=$work/prefix
unset PARSONS_DATA_DIR

fail() {
    echo "FAIL: $*" >&2
    exit 1
}
must_have() { # must_have LIST PATH...: each path is a line of LIST
    local list=$1
    shift
    for p in "$@"; do
        grep -qxF "$p" <<<"$list" || fail "$p is not in the installed tree"
    done
}

echo "== cmake --install --prefix $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
tree=$(cd "$prefix" && find . -type f | sed 's|^\./||' | sort)
must_have "$tree" bin/parsons \
    share/man/man1/parsons.1 share/man/man1/parsons-run.1 share/man/man1/parsons-gen-tapping.1 \
    share/bash-completion/completions/parsons share/zsh/vendor-completions/_parsons \
    share/doc/parsons/README.md share/doc/parsons/LICENSE share/doc/parsons/CHANGELOG.md \
    share/doc/parsons/docs/design-rules.md share/doc/parsons/docs/install.md \
    share/doc/parsons/examples/relay_events.cpp share/doc/parsons/examples/CMakeLists.txt \
    share/parsons/airfoils/clarky.dat share/parsons/airfoils/naca2412.dat \
    share/parsons/samples/patent-example.csv \
    include/parsons/cardreader/layout.hpp include/parsons/relaylogic/control_cabinet.hpp \
    include/parsons/axes/machine_profile.hpp include/parsons/decks/move_planner.hpp \
    lib/libparsons_cardreader.a lib/libparsons_relaylogic.a lib/libparsons_axes.a \
    lib/libparsons_decks.a lib/cmake/parsons/parsonsConfig.cmake \
    lib/cmake/parsons/parsonsConfigVersion.cmake lib/cmake/parsons/parsonsTargets.cmake
# Every page the build wrote is installed, and every header of the four parts.
for page in "$build"/man/man1/*.1; do
    must_have "$tree" "share/man/man1/$(basename "$page")"
done
for part in cardreader relaylogic axes decks; do
    for h in "$source/$part"/*.hpp; do
        must_have "$tree" "include/parsons/$part/$(basename "$h")"
    done
done
if grep -q "fuzz\|tests/\|parsons_tests" <<<"$tree"; then
    fail "test files were installed: $(grep "fuzz\|tests/\|parsons_tests" <<<"$tree" | head -3)"
fi
[ "$("$prefix/bin/parsons" --version)" = "$("$build/cli/parsons" --version)" ] ||
    fail "the installed parsons --version differs from the build's"

echo "== the installed parsons runs the demo, in a folder of its own"
mkdir -p "$work/run"
(cd "$work/run" && "$prefix/bin/parsons" demo >"$work/demo.log" 2>&1) || fail "parsons demo: exit $?"
grep -q "status         completed" "$work/demo.log" &&
    grep -q "every hole within tolerance" "$work/demo.log" ||
    fail "the demo did not run to its end: $(tail -5 "$work/demo.log")"
[ -s "$work/run/out/demo/airfoil-template/report.json" ] || fail "the demo wrote no report"
# The shipped sample deck, found in PREFIX/share/parsons, ran too, and the index names it.
[ -s "$work/run/out/demo/sample-deck/report.json" ] ||
    fail "the demo did not find the shipped sample deck: $(grep -m1 "^1\." "$work/demo.log")"
grep -q 'href="sample-deck/replay.html"' "$work/run/out/demo/index.html" ||
    fail "the demo's index.html does not show the sample deck"

echo "== it finds its bundled airfoil files by name, from any folder"
(cd "$work/run" && "$prefix/bin/parsons" gen airfoil --dat clarky --scallop 0.002 -o clarky.cbn \
    >"$work/gen.log") || fail "gen airfoil --dat clarky: exit $?"
grep -q "\"dat $prefix/share/parsons/airfoils/clarky.dat\"" "$work/run/clarky.cbn.job.json" ||
    fail "the job file does not name the installed clarky.dat"
(cd "$work/run" && "$build/cli/parsons" gen airfoil --dat e387.dat -o e387.cbn >/dev/null) ||
    fail "the build tree's parsons cannot find its airfoil files (build/share/parsons)"
grep -q "\"dat $build/share/parsons/airfoils/e387.dat\"" "$work/run/e387.cbn.job.json" ||
    fail "the build tree's job file does not name build/share/parsons/airfoils/e387.dat"
set +e
(cd "$work/run" && "$prefix/bin/parsons" gen airfoil --dat no-such-foil -o x.cbn 2>"$work/err.log")
code=$?
set -e
[ $code -eq 2 ] || fail "an unknown airfoil gave exit $code, not 2"
grep -q "no-such-foil: cannot open the airfoil file (bundled, by name: clarky.dat, e387.dat" \
    "$work/err.log" || fail "the unknown airfoil's message: $(cat "$work/err.log")"

echo "== examples/ builds against the installed package and runs"
cmake -S "$source/examples" -B "$work/examples" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >"$work/examples-configure.log" ||
    fail "configuring examples/: $(tail -20 "$work/examples-configure.log")"
grep -q "$prefix/lib/cmake/parsons" "$work/examples/CMakeCache.txt" ||
    fail "examples/ did not find the installed package"
cmake --build "$work/examples" >"$work/examples-build.log" 2>&1 ||
    fail "building examples/: $(tail -20 "$work/examples-build.log")"
"$work/examples/relay_events" >"$work/relay_events.log" || fail "relay_events: exit $?"
grep -q "card 3 read (number 0003)" "$work/relay_events.log" || fail "relay_events read no card 3"
grep -q "3 cards read, .* relay changes, machine time .* s, completed" "$work/relay_events.log" ||
    fail "relay_events did not complete: $(tail -3 "$work/relay_events.log")"
grep -q "picks .*numeral" "$work/relay_events.log" || fail "relay_events printed no relay"
grep -q "table at 0.0... in, cross slide at 0.0... in" "$work/relay_events.log" ||
    fail "relay_events did not bring the table and the cross slide home"

echo "== cpack: the .deb"
cpack --config "$build/CPackConfig.cmake" -B "$work/package" >"$work/cpack.log" 2>&1 ||
    fail "cpack: $(tail -20 "$work/cpack.log")"
deb=$(ls "$work"/package/parsons_*.deb)
version=$(sed -n 's/^project(parsons VERSION \([0-9.]*\).*/\1/p' "$source/CMakeLists.txt")
[ "$(dpkg-deb -f "$deb" Package)" = parsons ] || fail "the package is not named parsons"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "the package version is not $version"
depends=$(dpkg-deb -f "$deb" Depends)
for dep in libc6 libstdc++6 libfmt9; do
    sed 's/, /\n/g; s/ ([^)]*)//g' <<<"$depends" | grep -qxF "$dep" || fail "Depends lacks $dep: $depends"
done
recommends=$(dpkg-deb -f "$deb" Recommends)
for dep in libfmt-dev nlohmann-json3-dev libeigen3-dev; do
    grep -q "$dep" <<<"$recommends" || fail "Recommends lacks $dep: $recommends"
done
contents=$(dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./||')
must_have "$contents" usr/bin/parsons usr/share/man/man1/parsons-run.1 \
    usr/share/bash-completion/completions/parsons usr/share/zsh/vendor-completions/_parsons \
    usr/share/parsons/airfoils/clarky.dat usr/share/parsons/samples/patent-example.csv \
    usr/include/parsons/relaylogic/control_cabinet.hpp usr/lib/cmake/parsons/parsonsConfig.cmake \
    usr/lib/libparsons_decks.a usr/share/doc/parsons/README.md
if grep -v '^usr/\|^$' <<<"$contents" | grep -q .; then
    fail "the .deb puts files outside /usr: $(grep -v '^usr/\|^$' <<<"$contents" | head -3)"
fi
dpkg-deb -x "$deb" "$work/unpacked"
(cd "$work/run" && "$work/unpacked/usr/bin/parsons" gen airfoil --dat naca2412.dat -o n.cbn \
    >/dev/null) || fail "the unpacked .deb's parsons cannot find its airfoil files"
echo "$deb: $(dpkg-deb -c "$deb" | wc -l) entries; Depends: $depends"
echo "all checked"
