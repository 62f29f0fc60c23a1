#!/usr/bin/env bash
# Installs Debian's poppler-utils (pdftotext, pdftoppm) if pdftotext is not on
# PATH: the tests of `snowroll paper --comment` read the PDF's text with it.
# Safe to run again (does nothing when installed); prints pdftotext's path.
set -euo pipefail

bin=$(command -v pdftotext || true)
if [ -z "$bin" ]; then
    echo "install-poppler: pdftotext not found, installing Debian's poppler-utils" >&2
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    export DEBIAN_FRONTEND=noninteractive
    # Another apt-get on the machine holds the lock for a while: wait for it.
    $sudo apt-get -o DPkg::Lock::Timeout=300 update -qq >&2
    $sudo apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends poppler-utils >&2
    bin=$(command -v pdftotext || true)
fi
if [ -z "$bin" ]; then
    echo "install-poppler: FAIL: pdftotext is still not on PATH after apt-get install" >&2
    exit 1
fi
echo "$bin"
