#!/usr/bin/env bash
# The package as a web developer gets it: packs it (bindings/wasm/pack), installs the tarball into
# a fresh project (consumer/, vite pinned by its lock file, from the npm registry), imports it under
# node (ES module), type-checks it with TypeScript as browser code and as node code, bundles five
# pages with vite (hedge-mesh; hedge-mesh/single, the wasm embedded; hedge-mesh in a module worker;
# hedge-mesh/three; hedge-mesh/worker, the worker helper) and two once more with webpack
# (loadHedge(), and the worker helper with its worker chunk), and loads, picks and edits a mesh in
# each in headless chromium (playwright-core from web/node_modules). Run by ./test after the WebAssembly node tests.
# HEDGE_WASM_SKIP_BUILD=1 packs the module already built.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/hedge-package-test.XXXXXX")
trap 'rm -rf "$work"' EXIT

HEDGE_NPM_OUT=$work/npm "$root/bindings/wasm/pack" >/dev/null
tarball=$(echo "$work"/npm/hedge-mesh-*.tgz)
echo "packed: $(basename "$tarball") ($(wc -c <"$tarball") bytes)"

mkdir "$work/project"
cp "$here"/consumer/* "$work/project/"
cd "$work/project"
npm ci --no-audit --no-fund --loglevel=error
npm install --no-save --no-audit --no-fund --loglevel=error "$tarball"

# What scenario.js must compute everywhere: two triangles, one split into two more.
version=$(node -p 'require("./node_modules/hedge-mesh/package.json").version')
expected='{"version":"'$version'","hitFace":0,"faces":4,"problems":[],"partialSync":true,"globals":["undefined","undefined"]}'
node node_check.mjs "$expected"
# The types: a browser build sees hedge.d.ts (no loadHedgeNode), node code sees node.d.ts.
npx tsc -p tsconfig.bundler.json
npx tsc -p tsconfig.node.json
npx vite build --logLevel warn
ls dist/assets | grep -q '\.wasm$' || {
  echo "package_test: vite emitted no .wasm asset" >&2
  exit 1
}
npx webpack --stats errors-warnings >webpack.log 2>&1 || {
  cat webpack.log >&2
  exit 1
}
if grep -q 'WARNING' webpack.log; then
  cat webpack.log >&2
  echo "package_test: webpack warned" >&2
  exit 1
fi
cp index.html remote.html dist/webpack/
HEDGE_REPO=$root node browser_check.mjs "$expected"
echo "package test: passed"
