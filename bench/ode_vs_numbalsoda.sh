#!/usr/bin/env bash
# snowroll's ODE path against numbalsoda's DOP853 on one trajectory of eq. (4)
# (issue 37, item 1): alpha 30 deg, b 0.01 m, r0 0.1 m, from rest to t = 100 s,
# rtol 1e-10, atol 1e-12. The two alternate, RUNS times each, in one call, so
# that both see the same machine:
#   snowroll: the `batch` example, N runs each timed on its own, the median;
#   numbalsoda: bench/peer_numbalsoda.py over N copies of the same angle in one
#   numba-compiled loop (CPU time / N).
# Both print their relative error at t = 100 s against the closed form of fn. 4.
# Prints every pair and, at the end, the median of each and their ratio.
#
# Environment: N (default 20000), RUNS (default 5), PYTHON (an interpreter with
# numba and numbalsoda; default: bench/setup-peers.sh's, installed when missing).
# Usage: bash bench/ode_vs_numbalsoda.sh   (from anywhere in a clone)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
N="${N:-20000}"
RUNS="${RUNS:-5}"
PYTHON="${PYTHON:-$(bash bench/setup-peers.sh)}"
cargo build --quiet --release -p snowroll --example batch
batch="${CARGO_TARGET_DIR:-target}/release/examples/batch"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
snow=()
peer=()
for run in $(seq "$RUNS"); do
    s_out="$("$batch" --model torque-cm --n "$N")"
    p_out="$("$PYTHON" bench/peer_numbalsoda.py --alphas "30:30:$N")"
    s_us=$(echo "$s_out" | sed -n 's/^per_trajectory_s=//p')
    p_us=$(echo "$p_out" | sed -n 's/^per_trajectory_s=//p')
    s_err=$(echo "$s_out" | sed -n 's/.*relative difference \([^ ]*\).*/\1/p')
    p_err=$(echo "$p_out" | sed -n 's/.*relative difference \([^ ]*\).*/\1/p')
    snow+=("$s_us")
    peer+=("$p_us")
    echo "run $run: snowroll $(python3 -c "print(f'{$s_us*1e6:.2f}')") us (error $s_err)," \
        "numbalsoda $(python3 -c "print(f'{$p_us*1e6:.2f}')") us (error $p_err)"
    [ "$run" = 1 ] && echo "$s_out" | grep '^steps'
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "${snow[*]}" "${peer[*]}" <<'PY'
import statistics, sys
s = [float(x) for x in sys.argv[1].split()]
p = [float(x) for x in sys.argv[2].split()]
ratios = sorted(b / a for a, b in zip(s, p))
print(f"median: snowroll {statistics.median(s) * 1e6:.2f} us, numbalsoda {statistics.median(p) * 1e6:.2f} us; "
      f"numbalsoda/snowroll per pair {ratios[0]:.2f} .. {ratios[-1]:.2f}, median {statistics.median(ratios):.2f}")
PY
