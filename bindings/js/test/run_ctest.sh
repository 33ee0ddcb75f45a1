#!/usr/bin/env bash
# CTest entry for the JavaScript package: runs its node tests on the WebAssembly build,
# or says loudly why it cannot and exits 77 (CTest's SKIP_RETURN_CODE).
here="$(cd "$(dirname "$0")/.." && pwd)"
if ! command -v node >/dev/null; then
  echo "SKIPPED: wasm tests need node (>= 18) on PATH"; exit 77
fi
if [ ! -f "$here/dist/impulse2d_wasm.wasm" ]; then
  echo "SKIPPED: no WebAssembly build at $here/dist; run bindings/js/build.sh (needs emscripten)"; exit 77
fi
cd "$here" && exec node --test test/
