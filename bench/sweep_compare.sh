#!/usr/bin/env bash
# snowroll sweep against SciPy (issue 12), each measured as whole processes
# in one run:
#
# (1) `snowroll sweep --model torque-cm --alpha-deg 29:31:N_SWEEP --snow-depth
#     0.01 --r0 0.1 --t-end 100 --rtol 1e-10 --atol 1e-12 --output s.csv`,
#     wall clock and CPU time (medians of RUNS runs) of the whole process
#     (start, grid, rows, CSV, fsync, rename) divided by N_SWEEP, against the median CPU time of one SciPy solve_ivp
#     (DOP853, same tolerances) at the same angles (bench/peer_scipy.py
#     --alphas, N_SCIPY of them); the ratio must reach MIN_RATIO. The last
#     rows of the two are checked to agree (final speed, 1e-9).
# (2) every circular model to t = 100 s at rtol 1e-8 over N_ALL points:
#     trajectories per second of the whole process, against MIN_RATE.
# (3) for reference, (1) with --method ode (the ODE path, no closed form).
# (4) the grid of (1) with numbalsoda's DOP853 (bench/peer_numbalsoda.py,
#     every trajectory in one numba-compiled loop): CPU time per trajectory,
#     and snowroll's ratio to it. numbalsoda is installed by
#     bench/setup-peers.sh (built from source: gfortran, cmake); when it
#     cannot be had, (4) is skipped with the reason.
#
# Usage: bash bench/sweep_compare.sh   (from anywhere in a clone)
# Environment: N_SWEEP (100000), N_SCIPY (300), RUNS (5), N_ALL (200000), MIN_RATIO
# (5000: at most 1 us a row against SciPy's 5 ms, issue 37), MIN_RATE (100000),
# PYTHON (python3), OUT_DIR (a temporary directory; its file system's fsync is
# part of the measured time), CARGO_TARGET_DIR (where cargo builds; target/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

N_SWEEP="${N_SWEEP:-100000}"
N_SCIPY="${N_SCIPY:-300}"
RUNS="${RUNS:-5}"
N_ALL="${N_ALL:-200000}"
MIN_RATIO="${MIN_RATIO:-5000}"
MIN_RATE="${MIN_RATE:-100000}"
PYTHON="${PYTHON:-python3}"
OUT_DIR="${OUT_DIR:-$(mktemp -d)}"

if ! "$PYTHON" -c 'import scipy.integrate, numpy' 2>/dev/null; then
    echo "installing scipy and numpy for $PYTHON ..." >&2
    "$PYTHON" -m pip install -q scipy numpy || "$PYTHON" -m pip install -q --user scipy numpy || {
        echo "sweep_compare.sh: could not install scipy and numpy for $PYTHON" >&2
        exit 2
    }
fi

echo "building snowroll (release) ..." >&2
cargo build --release --quiet -p snowroll-cli
bin="${CARGO_TARGET_DIR:-$PWD/target}/release/snowroll"

# "wall cpu": the medians over RUNS runs of a command's wall-clock seconds
# and its CPU seconds (user + system, every thread), the latter from
# getrusage of the finished child.
measure() {
    "$PYTHON" - "$RUNS" "$@" <<'PY'
import resource, statistics, subprocess, sys, time
runs, cmd = int(sys.argv[1]), sys.argv[2:]
walls, cpus = [], []
for _ in range(runs):
    r0, t0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
    subprocess.run(cmd, check=True)
    t1, r1 = time.perf_counter(), resource.getrusage(resource.RUSAGE_CHILDREN)
    walls.append(t1 - t0)
    cpus.append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
print(statistics.median(walls), statistics.median(cpus))
PY
}

sweep1=(sweep --model torque-cm --alpha-deg "29:31:$N_SWEEP" --snow-depth 0.01 --r0 0.1
    --t-end 100 --rtol 1e-10 --atol 1e-12 --quiet)
echo "== (1) snowroll ${sweep1[*]} --output s.csv ($RUNS runs, medians)"
"$bin" "${sweep1[@]}" --output "$OUT_DIR/s.csv" # warm the page cache
read -r t1 c1 < <(measure "$bin" "${sweep1[@]}" --output "$OUT_DIR/s.csv")
read -r t1_ode c1_ode < <(measure "$bin" "${sweep1[@]}" --method ode --output "$OUT_DIR/s-ode.csv")
echo "whole process: wall $t1 s, CPU $c1 s for $N_SWEEP trajectories (--method ode: wall $t1_ode s, CPU $c1_ode s)"

echo "== SciPy solve_ivp DOP853 at $N_SCIPY of those angles"
py_out="$("$PYTHON" bench/peer_scipy.py --alphas "29:31:$N_SWEEP" --n "$N_SCIPY")"
echo "$py_out"
py_s="$(sed -n 's/^per_trajectory_s=//p' <<<"$py_out")"
py_v="$(sed -n 's/^final t = .* v = \([^ ]*\) m\/s.*/\1/p' <<<"$py_out")"

echo "== numbalsoda DOP853 over the same grid"
nb_s=nan
nb_python="${NUMBALSODA_PYTHON:-}"
if [ -z "$nb_python" ]; then
    if "$PYTHON" -c 'import numbalsoda, numba' 2>/dev/null; then
        nb_python="$PYTHON"
    else
        nb_python="$(bash bench/setup-peers.sh)" || nb_python=""
    fi
fi
if [ -n "$nb_python" ] && nb_out="$("$nb_python" bench/peer_numbalsoda.py --alphas "29:31:$N_SWEEP")"; then
    echo "$nb_out"
    nb_s="$(sed -n 's/^per_trajectory_s=//p' <<<"$nb_out")"
else
    echo "numbalsoda not available: see bench/README.md (skipped)"
fi

all_models="snowless,torque-cm,torque-contact,energy,energy-thin,lagrangian-printed,quasi-circular,quasi-circular-lift"
per_model=$((N_ALL / 8))
echo "== (2) snowroll sweep --model (all 8 circular) --alpha-deg 20:60:$per_model --t-end 100 --rtol 1e-8"
read -r t2 c2 < <(RUNS=1 measure "$bin" sweep --model "$all_models" --alpha-deg "20:60:$per_model" \
    --t-end 100 --rtol 1e-8 --quiet --output "$OUT_DIR/all.csv")
read -r t2_ode c2_ode < <(RUNS=1 measure "$bin" sweep --model "$all_models" \
    --alpha-deg "20:60:$per_model" --t-end 100 --rtol 1e-8 --quiet --method ode \
    --output "$OUT_DIR/all-ode.csv")

"$PYTHON" - "$t1" "$t1_ode" "$N_SWEEP" "$py_s" "$py_v" "$OUT_DIR/s.csv" "$MIN_RATIO" \
    "$t2" "$t2_ode" "$((per_model * 8))" "$MIN_RATE" "$nb_s" "$c1" "$c2" <<'PY'
import sys
t1, t1_ode, n1, py_s, py_v, csv_path, min_ratio, t2, t2_ode, n2, min_rate, nb_s, c1, c2 = sys.argv[1:]
nb_s, c1, c2 = float(nb_s), float(c1), float(c2)
t1, t1_ode, py_s, py_v, t2, t2_ode = map(float, (t1, t1_ode, py_s, py_v, t2, t2_ode))
n1, n2, min_ratio, min_rate = int(n1), int(n2), float(min_ratio), float(min_rate)
lines = [l.rstrip("\n").split(",") for l in open(csv_path) if not l.startswith("#")]
column = {name: k for k, name in enumerate(lines[0])}
last = lines[-1]
v = float(last[column["v_m_s"]])
diff = abs(v - py_v) / py_v
print(f"last row (alpha {last[column['alpha_deg']]} deg): snowroll v = {v:.15e}, scipy {py_v:.15e} m/s, relative difference {diff:.1e}")
per = t1 / n1
ratio = py_s / per
print(f"(1) per trajectory, process start and output included: snowroll {per * 1e6:.2f} us "
      f"(ODE path {t1_ode / n1 * 1e6:.2f} us), scipy {py_s * 1e3:.3f} ms: ratio {ratio:.0f}x "
      f"(ODE path {py_s / (t1_ode / n1):.0f}x; required >= {min_ratio:g}x)")
print(f"    CPU per trajectory (all threads, process included): snowroll {c1 / n1 * 1e6:.2f} us, "
      f"ratio {py_s / (c1 / n1):.0f}x")
if nb_s == nb_s:
    print(f"    numbalsoda DOP853 {nb_s * 1e6:.2f} us per trajectory (CPU, compiled loop): snowroll "
          f"{nb_s / per:.1f}x faster (ODE path {nb_s / (t1_ode / n1):.2f}x); scipy/numbalsoda "
          f"{py_s / nb_s:.0f}x")
rate = n2 / t2
print(f"(2) all circular models, t = 100 s, rtol 1e-8: {rate:,.0f} trajectories/s "
      f"(ODE path {n2 / t2_ode:,.0f}/s; required >= {min_rate:,.0f}/s); "
      f"{n2 / c2:,.0f} per CPU second")
bad = []
if not diff <= 1e-9:
    bad.append(f"the programs disagree by {diff:.1e}")
if ratio < min_ratio:
    bad.append(f"ratio {ratio:.0f}x below {min_ratio:g}x")
if rate < min_rate:
    bad.append(f"rate {rate:,.0f}/s below {min_rate:,.0f}/s")
if bad:
    sys.exit("sweep_compare.sh: " + "; ".join(bad))
PY
