#!/usr/bin/env bash
# `snowroll paper` at extreme scenarios (issue 22, item 5): each must exit 0
# and write its report, figures with nothing to show saying so. The test
# suite runs 85° (crates/snowroll-cli/tests/paper.rs); this script runs the
# others, which take most of a minute each in a debug build.
#   scripts/paper-extremes.sh [BINARY]   (default: target/release/snowroll)
set -euo pipefail
bin=${1:-${CARGO_TARGET_DIR:-target}/release/snowroll}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail=0
for scenario in "--alpha-deg 85" "--alpha-deg 1" "--snow-depth 0.1" "--snow-depth 0.5" \
    "--snow-depth 0.1 --alpha-deg 85" "--r0 0.001"; do
    # shellcheck disable=SC2086 # the scenario is several words
    if "$bin" paper --quiet --turns 10 $scenario --out "$dir/report" >"$dir/log" 2>&1 \
        && [ -f "$dir/report/report.html" ]; then
        echo "ok    paper $scenario"
    else
        echo "FAIL  paper $scenario"; tail -3 "$dir/log"; fail=1
    fi
done
exit $fail
