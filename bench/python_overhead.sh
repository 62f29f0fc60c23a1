#!/usr/bin/env bash
# What a Python call adds to the library's own time, and snowroll.sweep from
# numpy arrays against the CLI's sweep a row (issue 37, item 3): builds the
# Rust example one_call and the CLI (release), a release wheel of the Python
# package into the target directory (installed there, beside the venv of
# scripts/test-python.sh, not into it), then runs bench/python_overhead.py.
#
# Usage: bash bench/python_overhead.sh [ROUNDS] [N_SWEEP]   (defaults 5, 100000)
# Environment: CARGO_TARGET_DIR (else target/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$(pwd)
target=${CARGO_TARGET_DIR:-target}
case $target in
    /*) ;;
    *) target=$root/$target ;;
esac

bash scripts/test-python.sh --setup
venv=$target/pyenv-test
echo "building the example, the CLI and a release wheel ..." >&2
cargo build --release --quiet -p snowroll --example one_call
cargo build --release --quiet -p snowroll-cli
wheels=$target/wheels-bench
site=$target/pybench-site
rm -rf "$wheels" "$site"
"$venv/bin/maturin" build --release --quiet -m crates/snowroll-py/Cargo.toml \
    --interpreter "$venv/bin/python" --out "$wheels"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --no-deps \
    --target "$site" "$wheels"/snowroll-*.whl
cd "$target"
PYTHONPATH="$site" "$venv/bin/python" "$root/bench/python_overhead.py" \
    "$target/release/examples/one_call" "$target/release/snowroll" "${1:-5}" "${2:-100000}"
