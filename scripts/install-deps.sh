#!/usr/bin/env bash
# Installs what parsons needs, from Debian's packages only, and only what is missing. Safe to
# run again: with everything present it installs nothing and asks for nothing.
#
#   scripts/install-deps.sh            everything the build and the whole test suite need
#                                      (scripts/test.sh, scripts/build.sh)
#   scripts/install-deps.sh --program  only what the parsons program needs to build: the
#                                      compiler, cmake and four header libraries
#                                      (scripts/demo.sh)
set -euo pipefail

program_only=false
if [ "${1:-}" = "--program" ]; then
    program_only=true
elif [ $# -gt 0 ]; then
    echo "usage: scripts/install-deps.sh [--program]" >&2
    exit 2
fi

# The program: g++, cmake, make, the four libraries (fmt, CLI11, nlohmann-json, Eigen) and lld,
# the linker of both builds, some eight times faster than GNU ld on the test program
# (CMakeLists.txt). Then, for the tests:
# catch2: the test suite's framework (version 2). xxd: the docs' terminal sessions dump decks
# with it (tests/docs_commands_test.cpp).
# clang and libclang-rt-14-dev: clang's sanitizer runtimes and libFuzzer, for
# scripts/sanitize.sh and scripts/fuzz.sh (one build, build-sanitize/).
# gtkwave: its vcd2fst reads every trace the tests write, as GTKWave would; and xvfb: GTKWave
# itself opens the save file a run writes beside its trace, on a virtual display (xvfb-run).
# groff-base and zsh: the tests read the manual pages with groff and parse the zsh completion.
# dpkg-dev and file: CPack works out the .debs' Depends with dpkg-shlibdeps; lintian checks them.
# emscripten and node-acorn (its JavaScript optimizer's parser): the exhibit page, the emulator
# compiled to WebAssembly (cmake --preset wasm, docs/web.md). chromium: the page's tests in a
# real browser, headless (puppeteer-core drives it; nothing downloads a browser).
packages=(g++ cmake make lld libfmt-dev libcli11-dev nlohmann-json3-dev libeigen3-dev)
if ! $program_only; then
    packages+=(dpkg-dev file lintian catch2 xxd
               gtkwave xvfb
               clang libclang-rt-14-dev groff-base zsh
               emscripten node-acorn chromium)
    # Node.js and npm: the tests' independent cross-checks (tests/js: Ajv validates every JSON
    # output against docs/schemas, gcode-toolpath reads the G-code parsons writes) and the
    # browser tests (puppeteer-core). Debian's own unless a node is already on the PATH.
    if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
        packages+=(nodejs npm)
    fi
fi

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

# The npm packages of tests/js, exactly as its lockfile pins them, when they are missing or
# older than the lockfile.
npm_packages() {
    local js
    js="$(dirname "$0")/../tests/js"
    if [ ! -f "$js/node_modules/.package-lock.json" ] ||
        [ "$js/package-lock.json" -nt "$js/node_modules/.package-lock.json" ]; then
        echo "parsons: installing the npm packages of tests/js (npm ci)" >&2
        (cd "$js" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error)
    fi
}

if [ ${#missing[@]} -eq 0 ]; then
    $program_only || npm_packages
    exit 0
fi

echo "parsons: installing ${missing[*]} (Debian packages)" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then
        sudo="sudo"
    else
        echo "parsons: need root (or sudo) to apt-get install: ${missing[*]}" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
$program_only || npm_packages
