#!/bin/sh
# The npm package built from the WebAssembly checker, tested as a user gets it: built by
# bindings/wasm/build.sh (reusing target/), packed with `npm pack`, installed into a fresh
# project where no Rust toolchain is on PATH, and its tests run there with Node's runner.
# Prints the seconds each step took.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
step() { echo "== $1: $(( $(date +%s) - started )) s"; }

started=$(date +%s)
rustup target add wasm32-unknown-unknown
step "wasm32 target"

started=$(date +%s)
bindings/wasm/build.sh
step "build (wasm-bindgen-cli, wasm, glue)"

started=$(date +%s)
project=$(mktemp -d)
trap 'rm -rf "$project"' EXIT
tarball=$(cd "${CARGO_TARGET_DIR:-target}/wasm/npm" && npm pack --silent --pack-destination "$project")
step "npm pack ($tarball)"

started=$(date +%s)
node=$(command -v node)
npm=$(command -v npm)
bare="$(dirname "$node"):/usr/bin:/bin"
if env PATH="$bare" sh -c 'command -v cargo || command -v rustc' >/dev/null; then
    echo "cargo or rustc is on $bare: the test would not show that no toolchain is needed" >&2
    exit 1
fi
cp bindings/wasm/test/*.test.mjs "$project/"
cd "$project"
echo '{ "name": "x3dcheck-wasm-test", "private": true, "type": "module" }' > package.json
env PATH="$bare" "$npm" install --no-audit --no-fund --silent "./$tarball"
step "npm install"

started=$(date +%s)
env PATH="$bare" X3DCHECK_REPO="$root" "$node" --test ./*.test.mjs
step "node --test"
