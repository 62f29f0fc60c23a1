#!/usr/bin/env bash
# `snowroll turns` in closed form against the ODE path (issue 21, item 5),
# measured as whole processes (start, every turn, the CSV written, fsync,
# rename) in one run, the two methods alternating so that a change of load
# hits both alike:
#
#   snowroll turns --model turns --turns N --method closed|ode -o t.csv
#
# for N in N_LIST, RUNS times each; prints the median wall and CPU (user +
# sys) seconds of each method and the ratio ode/closed, and checks that the
# two tables have the same number of rows. The brief's target: N = 10^6 in
# at most 1 s whole process on 2 cores. Then every column of the two tables
# over N_CHECK turns, the ODE at its tightest tolerance (rtol 1e-15): the
# largest difference, relative to the value (accelerations to G = g sin α,
# since they pass through 0), must be at most 1e-12. Over many more turns
# the ODE's own error grows (its global error, ~turns x rtol): that is the
# integrator's, not the closed form's.
#
# Usage: bash bench/turns_closed_form.sh   (from anywhere in a clone)
# Environment: N_LIST ("100000 1000000"), RUNS (3), N_CHECK (1000), BIN (a release binary;
# default target/release/snowroll of CARGO_TARGET_DIR, built if missing),
# OUT_DIR (a temporary directory).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

N_LIST="${N_LIST:-100000 1000000}"
RUNS="${RUNS:-3}"
TARGET="${CARGO_TARGET_DIR:-target}"
BIN="${BIN:-$TARGET/release/snowroll}"
if [[ ! -x "$BIN" ]]; then
  cargo build --release -p snowroll-cli
fi
OUT_DIR="${OUT_DIR:-$(mktemp -d)}"
echo "binary $BIN; load average: $(cut -d' ' -f1-3 /proc/loadavg); cores $(nproc)"

# One whole-process run: prints "wall cpu".
run() {
  /usr/bin/time -f "%e %U %S" -o "$OUT_DIR/time" \
    "$BIN" turns --model turns --turns "$1" --method "$2" -o "$OUT_DIR/$2.csv" 2>/dev/null
  awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' "$OUT_DIR/time"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

for n in $N_LIST; do
  : > "$OUT_DIR/closed.times"
  : > "$OUT_DIR/ode.times"
  for _ in $(seq "$RUNS"); do
    for m in closed ode; do
      run "$n" "$m" >> "$OUT_DIR/$m.times"
    done
  done
  rows_c=$(grep -vc '^#' "$OUT_DIR/closed.csv")
  rows_o=$(grep -vc '^#' "$OUT_DIR/ode.csv")
  [[ "$rows_c" == "$rows_o" ]] || { echo "rows differ: $rows_c vs $rows_o" >&2; exit 1; }
  wc_=$(cut -d' ' -f1 "$OUT_DIR/closed.times" | median)
  cc_=$(cut -d' ' -f2 "$OUT_DIR/closed.times" | median)
  wo_=$(cut -d' ' -f1 "$OUT_DIR/ode.times" | median)
  co_=$(cut -d' ' -f2 "$OUT_DIR/ode.times" | median)
  awk -v n="$n" -v wc="$wc_" -v cc="$cc_" -v wo="$wo_" -v co="$co_" 'BEGIN {
    printf "N = %d: closed %.3f s wall %.3f s cpu; ode %.3f s wall %.3f s cpu; ratio ode/closed wall %.2f cpu %.2f\n",
      n, wc, cc, wo, co, wo / wc, co / cc }'
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

N_CHECK="${N_CHECK:-1000}"
"$BIN" turns --model turns --turns "$N_CHECK" --method ode --rtol 1e-15 --atol 1e-30 \
  -o "$OUT_DIR/ode_check.csv" 2>/dev/null
"$BIN" turns --model turns --turns "$N_CHECK" -o "$OUT_DIR/closed_check.csv" 2>/dev/null
python3 - "$OUT_DIR/closed_check.csv" "$OUT_DIR/ode_check.csv" <<'PY'
import sys
def table(path):
    lines = [l for l in open(path) if not l.startswith("#")]
    names = lines[0].strip().split(",")
    return names, [l.strip().split(",") for l in lines[1:]]
names, closed = table(sys.argv[1])
_, ode = table(sys.argv[2])
assert len(closed) == len(ode), "row counts differ"
g_along = 9.81 * 0.5  # the default slope, 30 degrees
worst = {}
for a, b in zip(closed, ode):
    for name, x, y in zip(names, a, b):
        if x == y:
            continue
        x, y = float(x), float(y)
        scale = max(abs(y), g_along if "_a_" in name else 0.0)
        worst[name] = max(worst.get(name, 0.0), abs(x - y) / scale)
top = max(worst.values(), default=0.0)
for name in names:
    print(f"  {name}: {worst.get(name, 0.0):.1e}")
print(f"N = {len(closed)}: largest relative difference closed vs ode (rtol 1e-15) {top:.1e}")
sys.exit(0 if top <= 1e-12 else 1)
PY
