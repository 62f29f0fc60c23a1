#!/usr/bin/env bash
# The fuzz campaign of issue 7: random command lines and config files run
# in-process through `snowroll_cli::run_from` by the harness in
# crates/snowroll-cli/tests/fuzz/ (what each case must satisfy is listed
# there), at low priority. CI runs the same harness with 2000 cases.
# The same binary fuzzes `merge` and `sweep --resume` with damaged shards
# and partial files (tests/fuzz/shards.rs), SHARD_CASES cases.
#
#   scripts/fuzz.sh [CASES [SEED [SHARD_CASES]]]
#       (default 1000000 cases, seed 2026, 50000 shard cases)
#
# Writes the counts to target/fuzz/summary-SEED.txt (and those of the
# shards to summary-SEED.txt.shards) and prints them. A case
# that fails is shrunk to a minimal one and printed, and the script exits
# non-zero; a case that runs past the harness's bound ends it with
# "FUZZ HANG". Each finding gets a regression test in
# crates/snowroll-cli/tests/fuzz_findings.rs.
set -euo pipefail
cd "$(dirname "$0")/.."

cases=${1:-1000000}
seed=${2:-2026}
shard_cases=${3:-50000}
mkdir -p target/fuzz
summary="target/fuzz/summary-$seed.txt"
rm -f "$summary" "$summary.shards"

cargo test --quiet -p snowroll-cli --test fuzz --no-run
commit=$(git describe --always --dirty)
start=$(date +%s)
status=0
FUZZ_CASES="$cases" FUZZ_SEED="$seed" FUZZ_SUMMARY="$PWD/$summary" FUZZ_SHARD_CASES="$shard_cases" \
    nice -n 19 cargo test --quiet -p snowroll-cli --test fuzz -- --test-threads=1 || status=$?
end=$(date +%s)
if [[ -f "$summary" ]]; then
    echo "wall time $((end - start)) s" >> "$summary"
    echo "commit $commit" >> "$summary"
    cat "$summary"
fi
if [[ -f "$summary.shards" ]]; then
    cat "$summary.shards"
fi
exit "$status"
