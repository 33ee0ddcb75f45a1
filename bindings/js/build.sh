#!/usr/bin/env bash
# Builds impulse2d as WebAssembly with Debian's emscripten: the same library and C API as
# the native build, twice:
#   dist/impulse2d_wasm.{mjs,wasm}       scalar contact kernels, for every engine;
#   dist/impulse2d_wasm_simd.{mjs,wasm}  built with -msimd128: the 4-lane WebAssembly SIMD
#                                        kernels, for engines with SIMD (all current
#                                        browsers and node >= 16), giving the same bits.
# Each .mjs is an ES-module loader; src/index.js picks the module. Needs no network:
# Debian ships emscripten's system libraries built.
#   bindings/js/build.sh [build-dir]     (default: build-wasm at the repository root;
#                                         the SIMD library is built in <build-dir>/simd)
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

# build_library DIR EXTRA_FLAGS: configures and builds the static library in DIR.
build_library() {
  emcmake cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=Release -DI2D_BUILD_SHARED=OFF \
    -DI2D_BUILD_TESTS=OFF -DI2D_BUILD_BENCH=OFF -DI2D_BUILD_EXAMPLES=OFF -DI2D_WERROR=ON \
    -DCMAKE_C_FLAGS="$2" -DCMAKE_CXX_FLAGS="$2" >/dev/null
  cmake --build "$1" -j2 --target impulse2d
}

# link_module LIBRARY NAME: links LIBRARY into dist/NAME.mjs and dist/NAME.wasm.
link_module() {
  local library="$1" name="$2"
  # Export every public i2d_ function of the library (the same set the shared library's
  # version script lets out), plus malloc and free for the binding's scratch memory. The
  # binding reads the struct layouts from the library itself (i2d_get_field_infos).
  local exports
  exports=$(llvm-nm --defined-only -g "$library" 2>/dev/null | awk '$2 == "T" && $3 ~ /^i2d_/ { printf "\"_%s\",", $3 }')
  [ -n "$exports" ] || { echo "build.sh: no i2d_ symbols found in $library" >&2; exit 1; }
  # -sWASM_BIGINT: 64-bit ids cross as BigInt instead of split halves.
  # -sALLOW_MEMORY_GROWTH: worlds grow; the binding re-reads the heap after every call.
  # -sENVIRONMENT=web: the loader then needs neither require nor __dirname, which an ES
  # module lacks in node; the binding hands node the .wasm bytes itself (wasmBinary).
  # -sFILESYSTEM=0: the library does no I/O.
  # -sALLOW_TABLE_GROWTH with addFunction and removeFunction: the contact hooks are JS
  # functions the library calls through its function table (World.setPreSolve).
  emcc -O3 -flto "$library" -o "$dist/$name.mjs" \
    -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createImpulse2dModule \
    -sENVIRONMENT=web -sWASM_BIGINT=1 -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=16MB \
    -sFILESYSTEM=0 -sTOTAL_STACK=1MB -sALLOW_TABLE_GROWTH=1 \
    -sEXPORTED_FUNCTIONS="[${exports}\"_malloc\",\"_free\"]" \
    -sEXPORTED_RUNTIME_METHODS='["UTF8ToString","addFunction","removeFunction"]' \
    -sINCOMING_MODULE_JS_API='["wasmBinary","instantiateWasm","print","printErr","locateFile"]'
  echo "built $dist/$name.mjs and $dist/$name.wasm ($(stat -c %s "$dist/$name.wasm") bytes)"
}

# -flto: link-time optimisation inlines across the library's files, a few per cent faster
# in wasm (large_pyramid 4.24 -> 3.98 ms a step in node); the bits are unchanged (no
# contraction, no fast-math: the node tests compare the hashes).
mkdir -p "$dist"
build_library "$build" "-flto"
link_module "$build/capi/libimpulse2d.a" impulse2d_wasm
build_library "$build/simd" "-msimd128 -flto"
link_module "$build/simd/capi/libimpulse2d.a" impulse2d_wasm_simd
