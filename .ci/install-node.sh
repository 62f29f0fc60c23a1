#!/usr/bin/env bash
# Installs Debian's nodejs and npm if node is not on PATH; prints node's path.
# Used by scripts/test.sh and .ci/explorer-browser-test.sh; does nothing when
# node is installed.
set -euo pipefail
bin=$(command -v node || true)
if [ -z "$bin" ]; then
    echo "install-node: node not found, installing Debian's nodejs and npm" >&2
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq >&2
    $sudo apt-get install -y -qq --no-install-recommends nodejs npm >&2
    bin=$(command -v node || true)
fi
[ -n "$bin" ] || { echo "install-node: FAIL: node is still not on PATH" >&2; exit 1; }
echo "$bin"
