#!/usr/bin/env bash
# The Python package's tests (issue 13): a virtual environment in the cargo
# target directory ($CARGO_TARGET_DIR when set, else target/),
# pinned maturin, pytest and numpy (and dask, pandas and pyarrow), the wheel built ONCE from
# crates/snowroll-py and installed, then pytest against the CLI ($SNOWROLL_CLI,
# else the release build)
# (crates/snowroll-py/tests compare every value with the CLI's to the bit).
# Needs python3 (>= 3.9) with the venv module. Its stages, for
# scripts/test.sh (which runs each one beside other work): `--setup` only
# installs the environment, `--wheel` the environment and the wheel,
# `--tests` only runs pytest (against the wheel a `--wheel` run installed).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

# Cargo's own rule: a relative CARGO_TARGET_DIR is taken from the directory
# cargo runs in, here the repository root.
target=${CARGO_TARGET_DIR:-target}
case $target in
    /*) ;;
    *) target=$root/$target ;;
esac
venv=$target/pyenv-test
wheels=$target/wheels

setup() {
    if [ ! -x "$venv/bin/python" ]; then
        python3 -m venv "$venv"
    fi
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
        "maturin==1.16.0" "pytest==8.4.2" "numpy==2.3.4"
    # matplotlib for the tests of result.plot() (issue 22; not a dependency
    # of the package).
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
        "matplotlib==3.10.7"
    # Dask (scheduler, worker processes, dask.dataframe) with pandas and
    # pyarrow, so that the tests on a real LocalCluster and of snowroll.dask
    # run (issue 24); pip does nothing when they are installed.
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
        "dask[distributed,dataframe]==2025.9.1" "pandas==2.3.3" "pyarrow==21.0.0"
}

# One wheel, built once per run and reused by every test (profile pywheel
# of Cargo.toml: the test profile's settings).
wheel() {
    rm -f "$wheels"/snowroll-*.whl
    "$venv/bin/maturin" build --profile pywheel --quiet -m crates/snowroll-py/Cargo.toml \
        --interpreter "$venv/bin/python" --out "$wheels"
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
        --force-reinstall --no-deps "$wheels"/snowroll-*.whl
}

tests() {
    # The CLI the tests compare with, from the same sources: $SNOWROLL_CLI
    # when set (scripts/test.sh passes the one `cargo test` just built), else
    # the release build (a no-op when built).
    cli=${SNOWROLL_CLI:-}
    if [ -z "$cli" ]; then
        cargo build --release --quiet -p snowroll-cli
        cli=$target/release/snowroll
    fi
    # Run from the tests directory so that `import snowroll` is the
    # installed wheel, not the source tree.
    cd crates/snowroll-py/tests
    SNOWROLL_CLI="$cli" "$venv/bin/python" -m pytest -q -p no:cacheprovider .
}

# (`;`, not `&&`: under `&&` a failing command inside the function would
# not end the script.)
case ${1:-} in
    --setup) setup ;;
    --wheel) setup; wheel ;;
    --tests) tests ;;
    "") setup; wheel; tests ;;
    *) echo "usage: scripts/test-python.sh [--setup | --wheel | --tests]" >&2; exit 2 ;;
esac
