#!/usr/bin/env bash
# Installs what parsons needs to build and test, from Debian's packages only, and only what is
# missing. Safe to run again: with everything present it installs nothing and asks for nothing.
set -euo pipefail

# clang and libclang-rt-14-dev: clang's sanitizer runtimes and libFuzzer, for
# scripts/sanitize.sh and scripts/fuzz.sh (one build, build-sanitize/). lld: the linker of both
# builds, some eight times faster than GNU ld on the test program (CMakeLists.txt).
# groff-base and zsh: the tests read the manual pages with groff and parse the zsh completion.
# dpkg-dev and file: CPack works out the .deb's Depends with dpkg-shlibdeps.
# emscripten and node-acorn (its JavaScript optimizer's parser): the exhibit page, the emulator
# compiled to WebAssembly (cmake --preset wasm, docs/web.md). chromium: the page's tests in a
# real browser, headless (puppeteer-core drives it; nothing downloads a browser).
packages=(g++ cmake make dpkg-dev file libfmt-dev libcli11-dev nlohmann-json3-dev libeigen3-dev catch2
          gtkwave
          clang libclang-rt-14-dev lld groff-base zsh
          emscripten node-acorn chromium)
# Node.js and npm: the tests' independent cross-checks (tests/js: Ajv validates every JSON
# output against docs/schemas, gcode-toolpath reads the G-code parsons writes) and the browser
# tests (puppeteer-core). Debian's own unless a node is already on the PATH.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    packages+=(nodejs npm)
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
    npm_packages
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
npm_packages
