#!/usr/bin/env bash
# The project's test command (README): every Rust test of the workspace, the
# Python package's tests (scripts/test-python.sh), the Slurm job array of
# examples/slurm-sweep.sh on a one-node cluster (scripts/test-slurm.sh), then `snowroll paper
# --strict` (fails when any verdict differs from the one the claims table
# expects) and the browser test of the report it writes (installs
# Debian's chromium first if it is missing; needs root or sudo for that) and
# of `snowroll serve`'s page (.ci/serve-browser-test.sh), then
# scripts/check-guide.py (links of the docs, the user guide's examples).
# The Python environment is installed while cargo compiles, and the Slurm
# test runs beside the report's; each one's output is shown when it ends.
set -euo pipefail
cd "$(dirname "$0")/.."

# The Python tests' environment is installed (pip, mostly downloads) while
# cargo compiles; its log is shown only if it fails.
py_setup_log=$(mktemp)
bash scripts/test-python.sh --setup >"$py_setup_log" 2>&1 &
py_setup=$!
# shellcheck disable=SC2064 # expand now: the job and the log of this run
# (`set +e` first: under `set -e` a failing `kill` of a job already ended
# would end the trap, and the script, with its status.)
trap "set +e; kill $py_setup 2>/dev/null; rm -f '$py_setup_log'" EXIT

cargo test --workspace --all-features

if ! wait "$py_setup"; then
    cat "$py_setup_log" >&2
    echo "test: FAIL: setting up the Python tests' environment (scripts/test-python.sh --setup)" >&2
    exit 1
fi

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
# says so and skips). It mostly waits on the scheduler, so it runs beside the
# report and its browser test; Chromium is installed first (a no-op when it
# is) so that the two never run apt-get at once.
report_dir=$(mktemp -d)
slurm_log=$(mktemp)
bash .ci/install-chromium.sh >/dev/null
bash scripts/test-slurm.sh "$cli" >"$slurm_log" 2>&1 &
slurm=$!
# shellcheck disable=SC2064 # expand now: the job and the files of this run
trap "set +e; kill $slurm 2>/dev/null; wait $slurm 2>/dev/null; rm -rf '$report_dir' '$slurm_log' '$py_setup_log'" EXIT

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

slurm_status=0
wait "$slurm" || slurm_status=$?
cat "$slurm_log"
if [ "$slurm_status" -ne 0 ]; then
    echo "test: FAIL: scripts/test-slurm.sh exited $slurm_status" >&2
    exit "$slurm_status"
fi

# The user guide: every link of the README and docs/ resolves, and every
# example of docs/guide/ runs (the Python ones with the wheel just tested).
python3 scripts/check-guide.py "$cli" --python "$target/pyenv-test/bin/python"
