#!/usr/bin/env bash
# Builds impulse2d as WebAssembly with Debian's emscripten: the same library and C API as
# the native build, twice:
#   dist/impulse2d_wasm.{mjs,wasm}       scalar contact kernels, for every engine;
#   dist/impulse2d_wasm_simd.{mjs,wasm}  built with -msimd128: the 4-lane WebAssembly SIMD
#                                        kernels, for engines with SIMD (all current
#                                        browsers and node >= 16), giving the same bits.
#   dist/threads/impulse2d_wasm_threads.{js,wasm,worker.js}
#                                        SIMD and -pthread: worlds with worker_count > 1
#                                        step on Web Workers over shared memory (node, and
#                                        pages that are cross-origin isolated). A classic
#                                        script, not an ES module: emscripten 3.1.6's
#                                        threads need require() in node and importScripts
#                                        in its workers.
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

# link_module LIBRARY OUTPUT [EXTRA_FLAGS...]: links LIBRARY into dist/OUTPUT (the loader)
# and the .wasm beside it.
link_module() {
  local library="$1" output="$2"
  shift 2
  # Export every public i2d_ function of the library (the same set the shared library's
  # version script lets out), plus malloc and free for the binding's scratch memory. The
  # binding reads the struct layouts from the library itself (i2d_get_field_infos).
  local exports
  exports=$(llvm-nm --defined-only -g "$library" 2>/dev/null | awk '$2 == "T" && $3 ~ /^i2d_/ { printf "\"_%s\",", $3 }')
  [ -n "$exports" ] || { echo "build.sh: no i2d_ symbols found in $library" >&2; exit 1; }
  # -sWASM_BIGINT: 64-bit ids cross as BigInt instead of split halves.
  # -sALLOW_MEMORY_GROWTH: worlds grow; the binding re-reads the heap after every call.
  # -sFILESYSTEM=0: the library does no I/O.
  # -sALLOW_TABLE_GROWTH with addFunction and removeFunction: the contact hooks are JS
  # functions the library calls through its function table (World.setPreSolve).
  emcc -O3 -flto "$library" -o "$dist/$output" -sMODULARIZE=1 -sEXPORT_NAME=createImpulse2dModule \
    -sWASM_BIGINT=1 -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=16MB \
    -sFILESYSTEM=0 -sTOTAL_STACK=1MB -sALLOW_TABLE_GROWTH=1 \
    -sEXPORTED_FUNCTIONS="[${exports}\"_malloc\",\"_free\"]" \
    -sEXPORTED_RUNTIME_METHODS='["UTF8ToString","addFunction","removeFunction"]' \
    -sINCOMING_MODULE_JS_API='["wasmBinary","instantiateWasm","print","printErr","locateFile","mainScriptUrlOrBlob"]' \
    "$@"
  local wasm="$dist/${output%.*}.wasm"
  echo "built $dist/$output and $wasm ($(stat -c %s "$wasm") bytes)"
}

# The single-threaded builds are ES modules for the web: -sENVIRONMENT=web needs neither
# require nor __dirname, which an ES module lacks in node; the binding hands node the
# .wasm bytes itself (wasmBinary).
single_threaded=(-sEXPORT_ES6=1 -sENVIRONMENT=web)
# The threaded build keeps up to THREAD_POOL_SIZE workers started with the module
# (a page cannot start one while the step waits for it), so a world has at most
# THREAD_POOL_SIZE + 1 workers; the binding hands them out.
THREAD_POOL_SIZE=3
threaded=(-pthread -sENVIRONMENT=web,worker,node -sPTHREAD_POOL_SIZE=$THREAD_POOL_SIZE)

# -flto: link-time optimisation inlines across the library's files, a few per cent faster
# in wasm (large_pyramid 4.24 -> 3.98 ms a step in node); the bits are unchanged (no
# contraction, no fast-math: the node tests compare the hashes).
mkdir -p "$dist"
build_library "$build" "-flto"
link_module "$build/capi/libimpulse2d.a" impulse2d_wasm.mjs "${single_threaded[@]}"
build_library "$build/simd" "-msimd128 -flto"
link_module "$build/simd/capi/libimpulse2d.a" impulse2d_wasm_simd.mjs "${single_threaded[@]}"
build_library "$build/threads" "-msimd128 -pthread -flto"
# In dist/threads/ with a package.json of its own: the package's "type": "module" would
# make node read the loader and its worker script as ES modules.
mkdir -p "$dist/threads"
echo '{ "type": "commonjs" }' > "$dist/threads/package.json"
link_module "$build/threads/capi/libimpulse2d.a" threads/impulse2d_wasm_threads.js "${threaded[@]}"
