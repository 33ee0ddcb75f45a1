#!/usr/bin/env bash
# Builds impulse2d as WebAssembly with Debian's emscripten: the same library and C API as
# the native build, scalar contact kernels only (no x86 or NEON intrinsics exist in wasm),
# linked into bindings/js/dist/impulse2d_wasm.mjs (an ES-module loader) and
# impulse2d_wasm.wasm. Needs no network: Debian ships emscripten's system libraries built.
#   bindings/js/build.sh [build-dir]     (default: build-wasm at the repository root)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${1:-$root/build-wasm}"
dist="$here/dist"

command -v emcc >/dev/null || { echo "build.sh: emcc not found (apt-get install emscripten)" >&2; exit 2; }
# Debian's emscripten runs its JS tools (acorn, terser) with whatever node is first on
# PATH; a node that is not Debian's does not look in /usr/share/nodejs by itself.
if [ -d /usr/share/nodejs ]; then
  export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
fi

emcmake cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DI2D_BUILD_SHARED=OFF \
  -DI2D_BUILD_TESTS=OFF -DI2D_BUILD_BENCH=OFF -DI2D_BUILD_EXAMPLES=OFF -DI2D_WERROR=ON >/dev/null
cmake --build "$build" -j2 --target impulse2d

# Export every public i2d_ function of the library (the same set the shared library's
# version script lets out), plus malloc and free for the binding's scratch memory. The
# binding reads the struct layouts from the library itself (i2d_get_field_infos).
library="$build/capi/libimpulse2d.a"
exports=$(llvm-nm --defined-only -g "$library" 2>/dev/null | awk '$2 == "T" && $3 ~ /^i2d_/ { printf "\"_%s\",", $3 }')
[ -n "$exports" ] || { echo "build.sh: no i2d_ symbols found in $library" >&2; exit 1; }
mkdir -p "$dist"
# -sWASM_BIGINT: 64-bit ids cross as BigInt instead of split halves.
# -sALLOW_MEMORY_GROWTH: worlds grow; the binding re-reads the heap after every call.
# -sENVIRONMENT=web: the loader then needs neither require nor __dirname, which an ES
# module lacks in node; the binding hands node the .wasm bytes itself (wasmBinary).
# -sFILESYSTEM=0: the library does no I/O.
# -sALLOW_TABLE_GROWTH with addFunction and removeFunction: the contact hooks are JS
# functions the library calls through its function table (World.setPreSolve).
emcc -O3 "$library" -o "$dist/impulse2d_wasm.mjs" \
  -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createImpulse2dModule \
  -sENVIRONMENT=web -sWASM_BIGINT=1 -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=16MB \
  -sFILESYSTEM=0 -sTOTAL_STACK=1MB -sALLOW_TABLE_GROWTH=1 \
  -sEXPORTED_FUNCTIONS="[${exports}\"_malloc\",\"_free\"]" \
  -sEXPORTED_RUNTIME_METHODS='["UTF8ToString","addFunction","removeFunction"]' -sINCOMING_MODULE_JS_API='["wasmBinary","instantiateWasm","print","printErr","locateFile"]'
echo "built $dist/impulse2d_wasm.mjs and $dist/impulse2d_wasm.wasm ($(stat -c %s "$dist/impulse2d_wasm.wasm") bytes)"
