#!/usr/bin/env bash
# The project's test command (README): every Rust test of the workspace, the
# Python package's tests (scripts/test-python.sh), the Slurm job array of
# examples/slurm-sweep.sh on a one-node cluster (scripts/test-slurm.sh), then `snowroll paper
# --strict` (fails when any verdict differs from the one the claims table
# expects) and the browser test of the report it writes (installs
# Debian's chromium first if it is missing; needs root or sudo for that) and
# of `snowroll serve`'s page (.ci/serve-browser-test.sh), then
# scripts/check-guide.py (links of the docs, the user guide's examples).
set -euo pipefail
cd "$(dirname "$0")/.."

cargo test --workspace --all-features

# The program those tests ran (the test profile: the same numbers to the
# bit as a release build, since Rust never reassociates floating point; no
# second compile of the CLI's dependencies).
target=${CARGO_TARGET_DIR:-target}
case $target in
    /*) ;;
    *) target=$(pwd)/$target ;;
esac
cli=$target/debug/snowroll

# The Python package: one wheel, pytest against that CLI.
SNOWROLL_CLI=$cli bash scripts/test-python.sh

# examples/slurm-sweep.sh on a one-node Slurm cluster started here (installs
# Debian's slurm-wlm and munge first if missing; needs root or sudo, else it
# says so and skips).
bash scripts/test-slurm.sh "$cli"

report_dir=$(mktemp -d)
trap 'rm -rf "$report_dir"' EXIT
"$cli" paper --strict --quiet --out "$report_dir"
bash .ci/browser-test.sh "$report_dir"
# Keep the screenshots as artifacts of the run.
mkdir -p target/browser-test
cp "$report_dir"/browser-*.png target/browser-test/ 2>/dev/null || true
# `snowroll serve`: the page in the same browser; the slider's move, the
# plots and the readout against the API (the binary above has the feature:
# `cargo test --all-features` built it).
bash .ci/serve-browser-test.sh "$cli" target/browser-test
echo "browser test artifacts: target/browser-test/"
echo "browser: 2 passed, 0 failed"

# The user guide: every link of the README and docs/ resolves, and every
# example of docs/guide/ runs (the Python ones with the wheel just tested).
python3 scripts/check-guide.py "$cli" --python "$target/pyenv-test/bin/python"
