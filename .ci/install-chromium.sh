#!/usr/bin/env bash
# Installs Debian's chromium if no Chromium is on PATH; prints the binary's path.
# Used by .ci/browser-test.sh; safe to run again (does nothing when installed).
set -euo pipefail

find_chromium() { command -v chromium || command -v chromium-browser || true; }

bin=$(find_chromium)
if [ -z "$bin" ]; then
    echo "install-chromium: chromium not found, installing Debian's package" >&2
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq >&2
    $sudo apt-get install -y -qq --no-install-recommends chromium fonts-dejavu-core >&2
    bin=$(find_chromium)
fi
if [ -z "$bin" ]; then
    echo "install-chromium: FAIL: chromium is still not on PATH after apt-get install" >&2
    exit 1
fi
echo "$bin"
