#!/usr/bin/env bash
# Puts the WebAssembly checker beside the page: copies target/wasm/web/* (wasm-bindgen
# `--target web` output of bindings/wasm/build.sh) into web/pkg/, which git ignores.
# Runs bindings/wasm/build.sh first when its output is missing.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/target/wasm/web"

if [ ! -f "$out/x3dcheck_wasm.js" ] || [ ! -f "$out/x3dcheck_wasm_bg.wasm" ]; then
    bash "$root/bindings/wasm/build.sh"
fi

rm -rf "$root/web/pkg"
mkdir -p "$root/web/pkg"
cp -a "$out"/. "$root/web/pkg/"
echo "web/pkg: $(ls "$root/web/pkg" | tr '\n' ' ')"
