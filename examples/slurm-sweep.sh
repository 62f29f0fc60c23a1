#!/usr/bin/env bash
# A large `snowroll sweep` spread over a Slurm job array, then merged.
#
#   sbatch --array=0-15 examples/slurm-sweep.sh        # 16 tasks, one shard each
#   # when all have finished:
#   SHARDS=16 bash examples/slurm-sweep.sh merge       # sweep.csv, checked and in grid order
#
# Each task runs slice $SLURM_ARRAY_TASK_ID of $SHARDS equal, contiguous slices
# of the grid (`--shard I/N`, 0-based) and writes sweep-I.csv. A task that is
# killed (time limit, pre-emption) leaves sweep-I.csv.partial; resubmitting
# the same array index continues it (`--resume`) and gives the same file as an
# uninterrupted run. The rows do not depend on the number of CPUs a task gets,
# so tasks may land on any node. `snowroll merge` refuses a missing,
# duplicated or unfinished shard.
#
# Environment: SHARDS (default 16), OUT (output directory, default .),
# SNOWROLL (the program, default snowroll on PATH), GRID_FLAGS (the grid's
# flags as one string, split at spaces, instead of the grid below; the test
# scripts/test-slurm.sh uses it for a smaller grid). sbatch passes the
# environment of the submitting shell on to the tasks.
#SBATCH --job-name=snowroll-sweep
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
#SBATCH --requeue
set -euo pipefail

SHARDS="${SHARDS:-16}"
OUT="${OUT:-.}"
SNOWROLL="${SNOWROLL:-snowroll}"

# The grid: every axis of the sweep, as on the command line.
GRID=(--model torque-cm,torque-contact,energy,quasi-circular
    --alpha-deg 1:89:2000 --snow-depth 0.0001:0.1:500 --t-end 100)
if [[ -n "${GRID_FLAGS:-}" ]]; then read -ra GRID <<<"$GRID_FLAGS"; fi

if [[ "${1:-}" == "merge" ]]; then
    files=()
    for ((i = 0; i < SHARDS; i++)); do files+=("$OUT/sweep-$i.csv"); done
    exec "$SNOWROLL" merge "${files[@]}" -o "$OUT/sweep.csv"
fi

i="${SLURM_ARRAY_TASK_ID:?run this through sbatch --array=0-$((SHARDS - 1)), or pass merge}"
export RAYON_NUM_THREADS="${SLURM_CPUS_PER_TASK:-1}"
resume=()
[[ -e "$OUT/sweep-$i.csv.partial" ]] && resume=(--resume)
exec "$SNOWROLL" sweep "${GRID[@]}" --shard "$i/$SHARDS" --quiet \
    --output "$OUT/sweep-$i.csv" "${resume[@]}"
