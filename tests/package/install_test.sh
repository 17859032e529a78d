#!/usr/bin/env bash
# The install and the .debs, as a user gets them (docs/install.md): `cmake --install` into a
# temporary prefix, whose parsons runs the demo and finds its bundled data from any folder; then
# `cpack` makes the two packages, parsons and parsons-dev, whose fields, contents, stripping and
# lintian's verdict are checked, and the examples build against the unpacked pair.
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
    share/man/man1/parsons.1.gz share/man/man1/parsons-run.1.gz \
    share/man/man1/parsons-gen-tapping.1.gz \
    share/bash-completion/completions/parsons share/zsh/vendor-completions/_parsons \
    share/doc/parsons/README.md share/doc/parsons/copyright share/doc/parsons/CHANGELOG.md \
    share/doc/parsons/changelog.gz share/doc/parsons/airfoil-sources.md \
    share/doc/parsons/docs/design-rules.md share/doc/parsons/docs/install.md \
    share/doc/parsons-dev/copyright share/doc/parsons-dev/changelog.gz \
    share/doc/parsons-dev/examples/relay_events.cpp share/doc/parsons-dev/examples/CMakeLists.txt \
    share/parsons/airfoils/clarky.dat share/parsons/airfoils/naca2412.dat \
    share/parsons/samples/patent-example.csv \
    include/parsons/cardreader/layout.hpp include/parsons/relaylogic/control_cabinet.hpp \
    include/parsons/axes/machine_profile.hpp include/parsons/decks/move_planner.hpp \
    lib/libparsons_cardreader.a lib/libparsons_relaylogic.a lib/libparsons_axes.a \
    lib/libparsons_decks.a lib/cmake/parsons/parsonsConfig.cmake \
    lib/cmake/parsons/parsonsConfigVersion.cmake lib/cmake/parsons/parsonsTargets.cmake
# Every page the build wrote is installed, gzipped as gzip -9n gives it (no name, no time: the
# same bytes every build), and every header of the four parts.
for page in "$build"/man/man1/*.1; do
    must_have "$tree" "share/man/man1/$(basename "$page").gz"
    cmp -s <(gzip -9n -c "$page") "$prefix/share/man/man1/$(basename "$page").gz" ||
        fail "share/man/man1/$(basename "$page").gz is not the page gzipped -9n"
done
if grep -q "share/man/man1/.*\.1$" <<<"$tree"; then
    fail "an uncompressed manual page was installed: $(grep -m1 "share/man/man1/.*\.1$" <<<"$tree")"
fi
if grep -q "share/parsons/airfoils/SOURCES.md" <<<"$tree"; then
    fail "the airfoils' provenance was installed with the data, not with the docs"
fi
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

echo "== cpack: the two packages"
cpack --config "$build/CPackConfig.cmake" -B "$work/package" >"$work/cpack.log" 2>&1 ||
    fail "cpack: $(tail -20 "$work/cpack.log")"
version=$(sed -n 's/^project(parsons VERSION \([0-9.]*\).*/\1/p' "$source/CMakeLists.txt")
deb=$(ls "$work"/package/parsons_*.deb)
dev=$(ls "$work"/package/parsons-dev_*.deb)
field() { dpkg-deb -f "$1" "$2"; }
list_has() { # list_has "a, b (>= 1), c" b: b is one of the comma-separated package names
    local names
    names=$(sed 's/, /\n/g; s/ ([^)]*)//g' <<<"$1")
    grep -qxF "$2" <<<"$names"
}
[ "$(field "$deb" Package)" = parsons ] || fail "the program's package is not named parsons"
[ "$(field "$dev" Package)" = parsons-dev ] || fail "the library's package is not named parsons-dev"
for d in "$deb" "$dev"; do
    [ "$(field "$d" Version)" = "$version" ] || fail "$(basename "$d"): version is not $version"
    # A clean Description: a synopsis and an extended text, no CMake list separator in it.
    desc=$(field "$d" Description)
    if grep -q ";" <<<"$desc"; then fail "$(basename "$d"): a ';' in the Description: $desc"; fi
    [ "$(wc -l <<<"$desc")" -ge 3 ] || fail "$(basename "$d"): no extended description: $desc"
    # apt installs Recommends by default: no compiler, cmake or -dev package there.
    if field "$d" Recommends | grep -Eq "g\+\+|cmake|-dev|clang"; then
        fail "$(basename "$d") recommends a toolchain: $(field "$d" Recommends)"
    fi
done
depends=$(field "$deb" Depends)
for p in libc6 libstdc++6 libfmt9; do
    list_has "$depends" "$p" || fail "parsons' Depends lacks $p: $depends"
done
dev_depends=$(field "$dev" Depends)
for p in parsons libfmt-dev nlohmann-json3-dev libeigen3-dev; do
    list_has "$dev_depends" "$p" || fail "parsons-dev's Depends lacks $p: $dev_depends"
done
grep -qF "parsons (= $version)" <<<"$dev_depends" || fail "parsons-dev does not need parsons $version"
contents_of() { dpkg-deb -c "$1" | awk '{print $6}' | sed 's|^\./||'; }
contents=$(contents_of "$deb")
dev_contents=$(contents_of "$dev")
must_have "$contents" usr/bin/parsons usr/share/man/man1/parsons-run.1.gz \
    usr/share/bash-completion/completions/parsons usr/share/zsh/vendor-completions/_parsons \
    usr/share/parsons/airfoils/clarky.dat usr/share/parsons/samples/patent-example.csv \
    usr/share/doc/parsons/README.md usr/share/doc/parsons/copyright usr/share/doc/parsons/changelog.gz
must_have "$dev_contents" usr/include/parsons/relaylogic/control_cabinet.hpp \
    usr/lib/cmake/parsons/parsonsConfig.cmake usr/lib/libparsons_decks.a \
    usr/share/doc/parsons-dev/copyright usr/share/doc/parsons-dev/changelog.gz \
    usr/share/doc/parsons-dev/examples/relay_events.cpp
if grep -q "^usr/include/\|^usr/lib/" <<<"$contents"; then
    fail "parsons carries the library's files: $(grep -m1 "^usr/include/\|^usr/lib/" <<<"$contents")"
fi
if grep -q "^usr/bin/\|^usr/share/parsons/\|^usr/share/man/" <<<"$dev_contents"; then
    fail "parsons-dev carries the program's files: $(grep -m1 "^usr/bin/\|^usr/share/" <<<"$dev_contents")"
fi
for c in "$contents" "$dev_contents"; do
    if grep -v '^usr/\|^$' <<<"$c" | grep -q .; then
        fail "a .deb puts files outside /usr: $(grep -v '^usr/\|^$' <<<"$c" | head -3)"
    fi
done
# The copyright file is Debian's machine-readable format, the licence text the project's.
unpacked=$work/unpacked
dpkg-deb -x "$deb" "$unpacked"
dpkg-deb -x "$dev" "$unpacked"
copyright=$unpacked/usr/share/doc/parsons/copyright
head -1 "$copyright" | grep -qx "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/" ||
    fail "the copyright file is not in the machine-readable format"
grep -q "^Files: \*$" "$copyright" && grep -q "^License: Expat$" "$copyright" ||
    fail "the copyright file has no Files: * paragraph with its licence"
diff <(sed -n '/^Permission is hereby granted/,$p' "$source/LICENSE") \
    <(sed -n '/^ Permission is hereby granted/,$p' "$copyright" | sed 's/^ //; s/^\.$//') >/dev/null ||
    fail "the copyright file's Expat text is not the project's LICENSE"
zcat "$unpacked/usr/share/doc/parsons/changelog.gz" | head -1 | grep -qx "parsons ($version) unstable; urgency=medium" ||
    fail "changelog.gz is no Debian changelog of $version"
# Stripped: the executable has no symbols, the libraries no debug sections but their symbols.
kind=$(file "$unpacked/usr/bin/parsons")
grep -q ", stripped" <<<"$kind" || fail "usr/bin/parsons is not stripped"
for part in cardreader relaylogic axes decks; do
    lib=$unpacked/usr/lib/libparsons_$part.a
    # (captured first: grep -q ending a pipe early would fail it under pipefail)
    sections=$(objdump -h "$lib")
    symbols=$(nm -C "$lib")
    if grep -q "\.debug_" <<<"$sections"; then fail "$lib keeps debug sections"; fi
    grep -q " T parsons::" <<<"$symbols" || fail "$lib has lost its symbol table"
done
(cd "$work/run" && "$unpacked/usr/bin/parsons" gen airfoil --dat naca2412.dat -o n.cbn \
    >/dev/null) || fail "the unpacked .deb's parsons cannot find its airfoil files"

# lintian, Debian's package checker: every tag it gives, at every level, must be one that
# docs/install.md's table explains (a row "| `TAG` | ...").
if command -v lintian >/dev/null; then
    explained=$(sed -n 's/^| `\([a-z0-9-]*\)` |.*/\1/p' "$source/docs/install.md" | sort -u)
    [ -n "$explained" ] || fail "docs/install.md explains no lintian tag"
    lintian -I --pedantic "$deb" "$dev" >"$work/lintian.log" 2>&1 || true
    tags=$(sed -n 's/^[EWIPX]: [a-z-]*: \([a-z0-9-]*\).*/\1/p' "$work/lintian.log" | sort -u)
    for t in $tags; do
        grep -qxF "$t" <<<"$explained" || fail "lintian: $t, which docs/install.md does not explain: $(grep -m1 " $t" "$work/lintian.log")"
    done
    echo "lintian: $(grep -c '^[EWIPX]: ' "$work/lintian.log") tags, all explained: $(tr '\n' ' ' <<<"$tags")"
else
    echo "lintian is not installed (scripts/install-deps.sh installs it): not run"
fi

echo "== examples/, as parsons-dev ships them, build against the unpacked packages and run"
cmake -S "$unpacked/usr/share/doc/parsons-dev/examples" -B "$work/examples" \
    -DCMAKE_PREFIX_PATH="$unpacked/usr" \
    -DCMAKE_BUILD_TYPE=Release >"$work/examples-configure.log" ||
    fail "configuring examples/: $(tail -20 "$work/examples-configure.log")"
grep -q "$unpacked/usr/lib/cmake/parsons" "$work/examples/CMakeCache.txt" ||
    fail "examples/ did not find the unpacked parsons-dev"
cmake --build "$work/examples" >"$work/examples-build.log" 2>&1 ||
    fail "building examples/: $(tail -20 "$work/examples-build.log")"
"$work/examples/relay_events" >"$work/relay_events.log" || fail "relay_events: exit $?"
grep -q "card 3 read (number 0003)" "$work/relay_events.log" || fail "relay_events read no card 3"
grep -q "3 cards read, .* relay changes, machine time .* s, completed" "$work/relay_events.log" ||
    fail "relay_events did not complete: $(tail -3 "$work/relay_events.log")"
grep -q "picks .*numeral" "$work/relay_events.log" || fail "relay_events printed no relay"
grep -q "table at 0.0... in, cross slide at 0.0... in" "$work/relay_events.log" ||
    fail "relay_events did not bring the table and the cross slide home"

echo "$(basename "$deb"): $(field "$deb" Installed-Size) kB installed, $(wc -l <<<"$contents") entries; Depends: $depends"
echo "$(basename "$dev"): $(field "$dev" Installed-Size) kB installed, $(wc -l <<<"$dev_contents") entries; Depends: $dev_depends"
echo "all checked"
