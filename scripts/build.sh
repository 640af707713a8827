#!/usr/bin/env bash
# Builds the native tree (core, CLI, tests) in build/native and the wasm module in build/wasm
# (written to web/public/wasm/). Incremental: a second run only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

build_native() {
  [ -f build/native/CMakeCache.txt ] ||
    cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build/native -j"$jobs"
}

build_wasm() {
  # Debian's emscripten runs its JS optimizer with node and needs Debian's acorn on NODE_PATH.
  export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
  [ -f build/wasm/CMakeCache.txt ] ||
    emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build/wasm -j"$jobs"
}

# AddressSanitizer + UndefinedBehaviorSanitizer build with clang-14: the native suite and the
# libFuzzer targets (scripts/fuzz.sh) share its instrumented core.
build_sanitize() {
  [ -f build/sanitize/CMakeCache.txt ] ||
    CC=clang-14 CXX=clang++-14 cmake -S . -B build/sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DTESSERA_SANITIZE=ON >/dev/null
  cmake --build build/sanitize -j"$jobs"
}

case "${1:-all}" in
  native) build_native ;;
  wasm) build_wasm ;;
  sanitize) build_sanitize ;;
  all) build_native && build_wasm ;;
  *) echo "usage: scripts/build.sh [native|wasm|sanitize|all]" >&2; exit 2 ;;
esac
