#!/usr/bin/env bash
# The web page's browser test (issue 34 item 4): `bash .ci/web.sh` from anywhere; .ci/run
# calls it after .ci/wasm.sh. Debian's Chromium (apt-get, never a downloaded browser)
# runs web/ headless, driven by playwright-core from package-lock.json.
set -euo pipefail

cd "$(dirname "$0")/.."

started=$SECONDS
step_started=$SECONDS
step() { printf '\n== %s\n' "$*"; step_started=$SECONDS; }
took() { echo "$1: $((SECONDS - step_started)) s"; }

step "Chromium (Debian's package) and Node.js"
if [ ! -x /usr/bin/chromium ] || ! command -v npm >/dev/null 2>&1; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q
    apt-get install -y -q --no-install-recommends chromium nodejs npm
fi
/usr/bin/chromium --version
node --version
took "Chromium and Node.js"

step "web/build.sh: the WebAssembly checker into web/pkg/"
bash web/build.sh
took "web/build.sh"

step "npm ci in web/test (playwright-core, no browser download)"
(cd web/test && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund)
took "npm ci"

step "the page in headless Chromium: node --test"
(cd web/test && CHROMIUM=/usr/bin/chromium node --test)
took "browser test"

echo "web: $((SECONDS - started)) s in all"
