#!/usr/bin/env bash
# `snowroll fit`'s speed (issue 35, item 3): a 2-parameter fit (alpha_deg
# and snow_depth free) of 200 SYNTHETIC points to one circular model must
# take at most 50 ms. Builds the example crates/snowroll/examples/fit_bench.rs
# in release and runs it for each model in MODELS; it times each fit on its
# own (median and mean over N fits after 3 untimed ones), checks the fit
# found the truth within 5 standard errors, and this script fails when a
# median is above LIMIT_MS.
#
# Usage: bash bench/fit.sh   (from anywhere in a clone)
# Environment: MODELS ("energy torque-cm torque-contact loney"), N (50),
# LIMIT_MS (50).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

MODELS="${MODELS:-energy torque-cm torque-contact loney}"
N="${N:-50}"
LIMIT_MS="${LIMIT_MS:-50}"
TARGET="${CARGO_TARGET_DIR:-target}"
cargo build --release -q -p snowroll --example fit_bench
status=0
for model in $MODELS; do
    line="$("$TARGET/release/examples/fit_bench" --model "$model" --n "$N")"
    echo "$line"
    median="$(sed -n 's/.*median \([0-9.]*\) ms.*/\1/p' <<<"$line")"
    if awk -v m="$median" -v l="$LIMIT_MS" 'BEGIN { exit !(m > l) }'; then
        echo "FAIL: $model median $median ms > $LIMIT_MS ms" >&2
        status=1
    fi
done
exit "$status"
