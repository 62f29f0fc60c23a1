#!/usr/bin/env bash
# The explorer's speed in headless Chromium: builds the one-file page
# (scripts/build-explorer.sh), opens it from file:// and moves the alpha
# slider 16 times per configuration (the first move a warm-up), timing each
# move from its input event to the redrawn page with the Performance API.
#
#   bash bench/explorer.sh [OUT.json]
#
# Prints and writes (OUT.json, default target/explorer-bench.json) the
# median and the largest time per configuration: the default circular
# models (torque-cm, loney), the turn model `turns` (100 s), and the three.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-target}
out=${1:-$target/explorer-bench.json}
chromium=$(bash .ci/install-chromium.sh)
node=$(bash .ci/install-node.sh)
node_dir=$target/explorer-node
if [ ! -f "$node_dir/node_modules/playwright-core/package.json" ]; then
    mkdir -p "$node_dir"
    npm install --prefix "$node_dir" --no-audit --no-fund --silent playwright-core@1.57.0
fi
page=$(mktemp --suffix=.html)
trap 'rm -f "$page"' EXIT
bash scripts/build-explorer.sh "$page"
# --cli is not run by the benchmark; the script asks for one.
PLAYWRIGHT_CORE=$(cd "$node_dir" && pwd)/node_modules/playwright-core \
    "$node" scripts/explorer/browser-test.js --chromium "$chromium" --cli /bin/true --page "$page" --bench "$out"
echo "bench/explorer.sh: wrote $out"
