#!/usr/bin/env bash
# The project's test command (README): every Rust test of the workspace, the
# Python package's tests (scripts/test-python.sh), the Slurm job array of
# examples/slurm-sweep.sh on a one-node cluster (scripts/test-slurm.sh), then `snowroll paper
# --strict` (fails when any verdict differs from the one the claims table
# expects) and the browser test of the report it writes (installs
# Debian's chromium first if it is missing; needs root or sudo for that) and
# of the explorer (scripts/build-explorer.sh, its WebAssembly against the
# CLI, and .ci/explorer-browser-test.sh: the page from file:// and under
# `snowroll serve`), then
# scripts/check-guide.py (links of the docs, the user guide's examples),
# and last a check that no test left a file in the tree.
#
# On 2 cores the order is chosen so that waiting overlaps work (issue 19,
# item 4; the whole took 412 s from a fresh clone when each step ran after
# the other): the Python environment is installed while cargo compiles, the
# Python wheel is built while the Rust tests run, and the Python tests run
# beside the report's browser tests and the Slurm test (those mostly wait
# on a browser or the scheduler). Each job's output is shown when it ends.
set -euo pipefail
cd "$(dirname "$0")/.."

# Files of this run and the jobs still running, removed and ended on exit
# (`set +e` first: under `set -e` a failing `kill` of a job already ended
# would end the trap, and the script, with its status).
files=()
jobs_running=()
cleanup() {
    set +e
    for job in "${jobs_running[@]}"; do
        kill "$job" 2>/dev/null
        wait "$job" 2>/dev/null
    done
    rm -rf "${files[@]}"
}
trap cleanup EXIT

# The files in the tree that git does not track, ignored ones included
# (outputs such as *.csv are ignored, so `git status` would not show them),
# each wholly untracked directory as one line; the build's directory and
# Python's caches are expected. Listed at the start and compared at the end
# (issue 33, item 7: two sweep outputs had been committed at the root).
target_in_tree=${CARGO_TARGET_DIR:-target}
target_in_tree=${target_in_tree#"$(pwd)"/}
untracked() {
    git ls-files --others --directory --no-empty-directory \
        | grep -v -x -F -e "target/" -e "${target_in_tree%/}/" \
        | grep -v -E '(^|/)__pycache__/$' | sort || true
}
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    untracked_before=$(untracked)
else
    untracked_before=none
fi

# When each background job started (seconds of this script), by its pid.
declare -A started
# Prints when a step ended, in seconds since this script started: the run's
# time line, to tell which step a slow run spent its time on.
stamp() {
    echo "test: $1 done at ${SECONDS} s"
}

# Starts `$@` in the background with its output in a file; sets $job, $log.
start() {
    log=$(mktemp)
    files+=("$log")
    "$@" >"$log" 2>&1 &
    job=$!
    jobs_running+=("$job")
    started[$job]=$SECONDS
}

# Waits for job $1 (log $2); shows its log when it fails (or always, with
# `show`) and then, on failure, ends the script naming $3.
finish() {
    local status=0 job
    wait "$1" || status=$?
    local still=()
    for job in "${jobs_running[@]}"; do
        [ "$job" = "$1" ] || still+=("$job")
    done
    jobs_running=("${still[@]}")
    if [ "$status" -ne 0 ] || [ "${4:-}" = show ]; then
        cat "$2"
    fi
    if [ "$status" -ne 0 ]; then
        echo "test: FAIL: $3 exited $status" >&2
        exit "$status"
    fi
    echo "test: $3 done at ${SECONDS} s (started at ${started[$1]} s)"
}

# pdftotext and pdftoppm (Debian's poppler-utils), which the tests of
# `snowroll paper --comment` read the PDF with: installed first (a no-op
# when they are), before any other step could run apt-get.
bash .ci/install-poppler.sh >/dev/null
stamp "the poppler-utils install check"

# The Python tests' environment is installed (pip, mostly downloads) while
# cargo compiles.
start bash scripts/test-python.sh --setup
py_setup=$job py_setup_log=$log

# How the browser tests start Chromium (.ci/browser/chromium.sh), with
# stand-in browsers that hang or die as Chromium has: about 15 s of waiting.
start bash .ci/browser/test-chromium.sh
chromium_unit=$job chromium_unit_log=$log

cargo test --workspace --all-features --no-run
stamp "the test build"

# The wheel (a second cargo build, of crates/snowroll-py) beside the Rust
# tests (which keep about one and a half of the 2 cores busy).
finish "$py_setup" "$py_setup_log" "scripts/test-python.sh --setup"
start bash scripts/test-python.sh --wheel
wheel=$job wheel_log=$log

cargo test --workspace --all-features
stamp "the Rust tests"

finish "$wheel" "$wheel_log" "scripts/test-python.sh --wheel"

# The program those tests ran (the test profile: the same numbers to the
# bit as a release build, since Rust never reassociates floating point; no
# second compile of the CLI's dependencies).
target=${CARGO_TARGET_DIR:-target}
case $target in
    /*) ;;
    *) target=$(pwd)/$target ;;
esac
cli=$target/debug/snowroll

# Chromium is installed first (a no-op when it is) so that it and the Slurm
# test never run apt-get at once.
bash .ci/install-chromium.sh >/dev/null
stamp "the Chromium install check"

# The explorer's one-file page (the library in WebAssembly; installs the
# wasm32 target first if missing), built beside the Python and Slurm tests,
# which mostly wait.
explorer_dir=$(mktemp -d)
files+=("$explorer_dir")
start bash scripts/build-explorer.sh "$explorer_dir/explorer.html"
explorer_job=$job explorer_log=$log

# The Python package's tests: pytest against that CLI.
start env SNOWROLL_CLI="$cli" bash scripts/test-python.sh --tests
pytest_job=$job pytest_log=$log

# examples/slurm-sweep.sh on a one-node Slurm cluster started here (installs
# Debian's slurm-wlm and munge first if missing; needs root or sudo, else it
# says so and skips), two copies at once, each its own cluster on ports
# picked free (issue 33, item 6: a second cluster on the machine had made
# the test fail). It mostly waits on the scheduler.
start bash scripts/test-slurm.sh --pair "$cli"
slurm=$job slurm_log=$log

report_dir=$(mktemp -d)
files+=("$report_dir")
"$cli" paper --strict --quiet --out "$report_dir"
# A Chromium try that fails keeps its whole log there too.
export CHROMIUM_FAILED_LOGS=$(pwd)/target/browser-test
bash .ci/browser-test.sh "$report_dir"
# Keep the screenshots as artifacts of the run.
mkdir -p target/browser-test
cp "$report_dir"/browser-*.png target/browser-test/ 2>/dev/null || true
# The explorer: the WebAssembly module's outputs against the CLI's, byte
# for byte (every model, both bodies, losses, CSV and JSON), then the page
# in the same browser from file:// and under `snowroll serve` (the binary
# above has the feature: `cargo test --all-features` built it).
finish "$explorer_job" "$explorer_log" "scripts/build-explorer.sh" show
"$(bash .ci/install-node.sh)" scripts/explorer/compare-cli.js "$cli" "$target/wasm32-unknown-unknown/release/snowroll_wasm.wasm"
bash .ci/explorer-browser-test.sh "$cli" "$explorer_dir/explorer.html" target/browser-test
echo "browser test artifacts: target/browser-test/"
echo "browser: 2 passed, 0 failed"
stamp "paper and the browser tests"

finish "$chromium_unit" "$chromium_unit_log" ".ci/browser/test-chromium.sh" show
finish "$pytest_job" "$pytest_log" "scripts/test-python.sh --tests" show
finish "$slurm" "$slurm_log" "scripts/test-slurm.sh" show

# The user guide: every link of the README and docs/ resolves, and every
# example of docs/guide/ runs (the Python ones with the wheel just tested).
python3 scripts/check-guide.py "$cli" --python "$target/pyenv-test/bin/python"

# No test left a file in the tree: what is untracked now was untracked
# before the tests.
if [ "$untracked_before" = none ]; then
    echo "test: not a git work tree, the check for files left in the tree is skipped"
else
    left=$(comm -13 <(printf '%s\n' "$untracked_before") <(untracked))
    if [ -n "$left" ]; then
        echo "test: FAIL: the tests left files in the tree (remove them; write outputs to a temporary directory):" >&2
        sed 's/^/  /' <<<"$left" >&2
        exit 1
    fi
    echo "test: no file left in the tree"
fi
