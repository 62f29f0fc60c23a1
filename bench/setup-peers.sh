#!/usr/bin/env bash
# Installs the Python peers of the sweep benchmark (SciPy, numba, numbalsoda)
# into a virtual environment, target/bench-venv, and prints its python.
# numbalsoda is built from source: gfortran and cmake come from Debian
# (apt-get, when missing and when run as root).
# Usage: bash bench/setup-peers.sh   (from anywhere in a clone)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

missing=()
command -v gfortran >/dev/null || missing+=(gfortran)
command -v cmake >/dev/null || missing+=(cmake)
if [ "${#missing[@]}" -gt 0 ]; then
    if [ "$(id -u)" = 0 ]; then
        echo "installing ${missing[*]} (Debian) ..." >&2
        apt-get update -qq >&2
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >&2
    else
        echo "setup-peers.sh: numbalsoda needs ${missing[*]}: apt-get install ${missing[*]}" >&2
        exit 2
    fi
fi

venv=target/bench-venv
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv" >&2
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
    -r bench/requirements-peers.txt >&2
echo "$PWD/$venv/bin/python"
