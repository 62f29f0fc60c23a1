#!/usr/bin/env bash
# Browser test of the explorer: the one-file page (scripts/build-explorer.sh)
# from file://, and the same page under `snowroll serve`, in Debian's
# headless Chromium (.ci/install-chromium.sh) driven by playwright-core over
# the DevTools protocol (installed from npm into target/explorer-node, a
# pinned version). What it checks: scripts/explorer/browser-test.js.
#
#   .ci/explorer-browser-test.sh SNOWROLL EXPLORER.html OUT_DIR
#
# SNOWROLL is a snowroll binary built with the `serve` feature. Screenshots
# at 1400 and 400 px are written to OUT_DIR (explorer.png, explorer-phone.png,
# and the unwinding roll's explorer-roll.png).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)
fail() { echo "explorer-browser-test: FAIL: $*" >&2; exit 1; }

[ $# -eq 3 ] || fail "usage: .ci/explorer-browser-test.sh SNOWROLL EXPLORER.html OUT_DIR"
snowroll=$1 page=$2
mkdir -p "$3"
out=$(cd "$3" && pwd)
chromium=$("$here/install-chromium.sh") || fail "Chromium is not available"
node=$("$here/install-node.sh") || fail "node is not available"

# playwright-core 1.57.0: no browser download (it drives the Chromium above).
node_dir=${CARGO_TARGET_DIR:-$root/target}/explorer-node
case $node_dir in /*) ;; *) node_dir=$root/$node_dir ;; esac
if [ ! -f "$node_dir/node_modules/playwright-core/package.json" ]; then
    mkdir -p "$node_dir"
    npm install --prefix "$node_dir" --no-audit --no-fund --silent playwright-core@1.57.0 >&2 \
        || fail "npm could not install playwright-core"
fi
# Chromium keeps its crash database, certificate store and caches under
# HOME whatever its --user-data-dir (see .ci/browser/chromium.sh): this run
# gets a home of its own, so that it shares none of them with another
# Chromium of the same user on the machine.
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
HOME=$home XDG_CONFIG_HOME=$home/.config XDG_CACHE_HOME=$home/.cache \
    PLAYWRIGHT_CORE=$node_dir/node_modules/playwright-core \
    timeout 300 "$node" "$root/scripts/explorer/browser-test.js" --chromium "$chromium" --cli "$snowroll" \
    --page "$page" --serve --shots "$out"
