#!/usr/bin/env bash
# Puts the WebAssembly checker beside the page: copies target/wasm/web/* (the wasm-bindgen
# `--target web` output of bindings/wasm/build.sh) into web/pkg/, which git ignores.
# Runs bindings/wasm/build.sh first when that output is missing; an output that is there
# is copied as it is (.ci/run builds it fresh in .ci/wasm.sh first).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
# Where bindings/wasm/build.sh writes (it respects CARGO_TARGET_DIR too).
out="${CARGO_TARGET_DIR:-target}/wasm/web"

if [ ! -f "$out/x3dcheck_wasm.js" ] || [ ! -f "$out/x3dcheck_wasm_bg.wasm" ]; then
    sh bindings/wasm/build.sh
fi

rm -rf web/pkg
mkdir -p web/pkg
cp -a "$out"/. web/pkg/
echo "web/pkg: $(ls web/pkg | tr '\n' ' ')"
