#!/usr/bin/env bash
# snowroll against SciPy on the issue-2 speed case: eq. (4), alpha 30 deg,
# b 0.01 m, r0 0.1 m, from rest to t = 100 s, rtol 1e-10, atol 1e-12, N runs.
# Prints the per-trajectory time of each program (median over the N runs:
# wall clock for snowroll, whose 20 us runs are almost never preempted, and
# thread CPU time for SciPy, whose 5 ms runs often are on a shared machine)
# and the ratio; exits non-zero if the ratio is below MIN_RATIO, or if the two
# programs' final speeds disagree.
#
# Usage: bash bench/compare.sh            (from anywhere in a clone)
# Environment: N (default 1000), MIN_RATIO (default 250), PYTHON (default python3).
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

N="${N:-1000}"
MIN_RATIO="${MIN_RATIO:-250}"
PYTHON="${PYTHON:-python3}"

# SciPy and NumPy: install only when missing.
if ! "$PYTHON" -c 'import scipy.integrate, numpy' 2>/dev/null; then
    echo "installing scipy and numpy for $PYTHON ..." >&2
    "$PYTHON" -m pip install -q scipy numpy \
        || "$PYTHON" -m pip install -q --user scipy numpy \
        || {
            echo "compare.sh: could not install scipy and numpy for $PYTHON;" \
                "make a virtual environment and set PYTHON=/path/to/venv/bin/python" >&2
            exit 2
        }
fi

echo "building snowroll (release) ..." >&2
cargo build --release --quiet -p snowroll --example batch

echo "== snowroll (Rust, DOP853) =="
rust_out="$(cargo run --release --quiet -p snowroll --example batch -- --model torque-cm --n "$N")"
echo "$rust_out"
echo
echo "== SciPy solve_ivp (DOP853) =="
py_out="$("$PYTHON" bench/peer_scipy.py --n "$N")"
echo "$py_out"
echo

per_trajectory() { sed -n 's/^per_trajectory_s=//p' <<<"$1"; }
final_v() { sed -n 's/^final t = .* v = \([^ ]*\) m\/s.*/\1/p' <<<"$1"; }
rust_s="$(per_trajectory "$rust_out")"
py_s="$(per_trajectory "$py_out")"
if [[ -z "$rust_s" || -z "$py_s" ]]; then
    echo "compare.sh: could not read a per-trajectory time" >&2
    exit 2
fi

# The two programs must solve the same problem: final speeds agree to far
# better than the tolerance-driven error (each is ~1e-14 from fn. 4).
SAME_ANSWER_RTOL=1e-9
"$PYTHON" - "$(final_v "$rust_out")" "$(final_v "$py_out")" "$SAME_ANSWER_RTOL" <<'PY'
import sys
rust, py, tol = map(float, sys.argv[1:])
diff = abs(rust - py) / abs(py)
print(f"final speed: snowroll {rust:.15e}, scipy {py:.15e} m/s, relative difference {diff:.1e}")
if not diff <= tol:
    sys.exit(f"compare.sh: the two programs disagree by {diff:.1e} > {tol:g}")
PY

"$PYTHON" - "$rust_s" "$py_s" "$MIN_RATIO" <<'PY'
import sys
rust, py, min_ratio = map(float, sys.argv[1:])
ratio = py / rust
print(f"per trajectory: snowroll {rust * 1e6:.2f} us, scipy {py * 1e3:.3f} ms, ratio {ratio:.0f}x (required >= {min_ratio:g}x)")
if ratio < min_ratio:
    sys.exit(f"compare.sh: snowroll is only {ratio:.0f}x faster than SciPy, below {min_ratio:g}x")
PY
