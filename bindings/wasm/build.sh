#!/bin/sh
# Builds the WebAssembly checker (bindings/wasm) and its JavaScript glue:
#   target/wasm/web/  the ES module for a web page (`import init, { check, rules, version }
#                     from './x3dcheck_wasm.js'; await init();`)
#   target/wasm/npm/  the npm package `x3dcheck` (Node >= 18 and browsers; `npm pack` it)
# wasm-bindgen's CLI must be the version of the wasm-bindgen crate in bindings/wasm/Cargo.lock: it is
# built from crates.io into target/tools when missing (no prebuilt download).
# Run from anywhere; CARGO_TARGET_DIR is respected.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
target=${CARGO_TARGET_DIR:-$root/target}
cd "$root"

seconds() { date +%s; }

version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' "$here/Cargo.lock")
bindgen=$target/tools/bin/wasm-bindgen
if ! [ -x "$bindgen" ] || [ "$("$bindgen" --version)" != "wasm-bindgen $version" ]; then
    start=$(seconds)
    # Only the wasm-bindgen command, without its default TLS feature (rustls and ring, for
    # the test runner's downloads): 7.8 minutes of CPU instead of 8.6. --locked first; a
    # registry mirror missing one of its locked dependencies gets the newest compatible
    # ones instead.
    set -- wasm-bindgen-cli --version "=$version" --no-default-features --bin wasm-bindgen --root "$target/tools"
    cargo install "$@" --locked || cargo install "$@"
    echo "wasm-bindgen-cli $version installed in $(( $(seconds) - start )) s"
fi

start=$(seconds)
cargo build --release --locked --target wasm32-unknown-unknown --manifest-path "$here/Cargo.toml" --target-dir "$target"
echo "wasm built in $(( $(seconds) - start )) s"
wasm=$target/wasm32-unknown-unknown/release/x3dcheck_wasm.wasm

start=$(seconds)
out=$target/wasm
rm -rf "$out/web" "$out/npm"
"$bindgen" --target web --out-dir "$out/web" "$wasm"
# The package: the same glue (ES module, loaded once per process) with two entry points,
# Node's (reads the .wasm from disk, synchronously) and the browsers' and bundlers'
# (fetches it next to the module), and the package files kept in bindings/wasm/npm.
mkdir -p "$out/npm"
cp "$out/web/x3dcheck_wasm.js" "$out/web/x3dcheck_wasm.d.ts" "$out/web/x3dcheck_wasm_bg.wasm" "$out/npm/"
cp "$here/npm/"* "$out/npm/"
cp "$root/LICENSE-MIT" "$root/LICENSE-APACHE" "$out/npm/"
sed -i "s/\"version\": \"[^\"]*\"/\"version\": \"$(awk -F'"' '/^version/ { print $2; exit }' "$here/Cargo.toml")\"/" "$out/npm/package.json"
echo "glue generated in $(( $(seconds) - start )) s; $(wc -c < "$out/web/x3dcheck_wasm_bg.wasm") bytes of wasm"
