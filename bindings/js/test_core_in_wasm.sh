#!/usr/bin/env bash
# Builds the library's own C and C++ test suites (unit, api, physics, determinism) with
# emscripten and runs them under node: the WebAssembly library passes the same tests as
# the native one, the recorded state hash included (bitwise the native results).
#   bindings/js/test_core_in_wasm.sh [build-dir]     (default: build-wasm-tests)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build-wasm-tests}"
command -v emcc >/dev/null || { echo "test_core_in_wasm.sh: emcc not found (apt-get install emscripten)" >&2; exit 2; }
[ -d /usr/share/nodejs ] && export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"

# SINGLE_FILE: emscripten 3.1.6's loader would fetch() a separate .wasm by path, which
# node's fetch refuses; ENVIRONMENT=node: the test programs run only there.
emcmake cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DI2D_BUILD_SHARED=OFF \
  -DI2D_BUILD_BENCH=OFF -DI2D_BUILD_EXAMPLES=OFF -DI2D_WERROR=ON \
  "-DCMAKE_EXE_LINKER_FLAGS=-sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=node" >/dev/null
# emcmake makes ctest run each test with "node --experimental-wasm-threads", an option
# node 20 no longer knows: plain node instead.
cmake -DCMAKE_CROSSCOMPILING_EMULATOR="$(command -v node)" "$build" >/dev/null
cmake --build "$build" -j2
# tools: they inspect a native shared library and install it; wasm: the JS package's
# own tests, run from the native build; long: as in the sanitizer run.
ctest --test-dir "$build" --output-on-failure -j2 -LE "tools|long|wasm"
