#!/usr/bin/env bash
# Proof that a refactoring changes no user-visible output, byte for byte.
#
#   scripts/same-outputs.sh run BINARY PYTHON OUTDIR
#       Runs a FIXED list of commands with the `snowroll` program BINARY and the
#       Python interpreter PYTHON (one whose environment has the `snowroll`
#       wheel installed) and writes every output into OUTDIR (created; it must
#       not exist or be empty). Per command NAME:
#         NAME.out  its stdout          NAME.err  its stderr
#         NAME.rc   its exit status     plus any file it writes (-o, paper/...)
#       A command that fails does not stop the run: its status is recorded, so
#       a refusal that appears, disappears or changes its message shows up.
#   scripts/same-outputs.sh compare DIR_A DIR_B
#       Compares two such directories byte for byte (every file, both ways);
#       prints the files that differ or exist on one side only and exits 1 if
#       any, 0 if the two are identical.
#
# Typical use (baseline from the old tree, then the new tree):
#   scripts/same-outputs.sh run OLD/snowroll OLDENV/bin/python /tmp/old
#   scripts/same-outputs.sh run NEW/snowroll NEWENV/bin/python /tmp/new
#   scripts/same-outputs.sh compare /tmp/old /tmp/new
#
# BINARY must be built with `--features parquet` (the parquet commands are in
# the list; without the feature they are refused and the comparison fails).
#
# What is compared, and why it is deterministic:
# - stdout, stderr and exit status of every command. No command here writes a
#   progress bar or a timing: progress bars are drawn only on a terminal and
#   stderr is always a file here (sweeps get -q and paper --quiet anyway);
#   turns' summary on stderr, warnings, notes and error messages are
#   deterministic text.
# - The program is always run as `snowroll` found on PATH (a symlink in a
#   private temporary directory), never by its path: clap prints argv[0]'s
#   file name in usage and error lines, and the sweep header records the
#   command line. Every command runs inside OUTDIR with relative file names,
#   so the recorded command lines are the same for any OUTDIR.
# - paper: EVERY file it writes is compared (report.html, report.md,
#   claims.json, data/*.csv, figures/*.svg and figures/*.png). Two runs of the
#   same binary gave identical bytes for all 46 files (checked when this
#   script was written: same-outputs.sh run twice, then compare; also with
#   one CPU, taskset -c 0), so none is left out. Its stdout names the output
#   directory, which is the fixed relative name `paper`. Note that report.md
#   and report.html quote source locations as text (`report::CLAIMS`,
#   tests/claims.rs, tests/losses.rs, crates/snowroll/tests/), and three
#   --help texts show rustdoc links ([`StopReason::Hop`], [`circular_end`],
#   [`FAST_MIN_RTOL`]): editing those when files move is a visible change and
#   shows up here.
# - Python: a snippet (below) writes every column of simulate(), turns() and
#   sweep() results with repr() of every float (shortest round-trip, so equal
#   text means equal bits) and the masks of masked arrays, plus the metadata
#   dicts, models(), and the messages of a few refused calls, into
#   python-api.txt. The snippet runs with `python -I -c`, so its warnings on
#   stderr name `<string>`, not a file path.
# - script.sha256: the checksum of this file. The commands are this file, so a
#   baseline made with another version of it is stale: rerun the baseline.
# - Sweeps run with rayon on all cores; their rows are the same bytes for any
#   thread count (a property the project tests), so the comparison holds
#   between machines of different core counts too.
set -euo pipefail

usage() {
    echo "usage: $0 run BINARY PYTHON OUTDIR | compare DIR_A DIR_B" >&2
    exit 2
}

# --- compare -----------------------------------------------------------------
compare() {
    local a=$1 b=$2
    [ -d "$a" ] || { echo "not a directory: $a" >&2; exit 2; }
    [ -d "$b" ] || { echo "not a directory: $b" >&2; exit 2; }
    local list_a list_b
    list_a=$(cd "$a" && find . \( -type f -o -type l \) | LC_ALL=C sort)
    list_b=$(cd "$b" && find . \( -type f -o -type l \) | LC_ALL=C sort)
    local bad=0 n=0 f
    while IFS= read -r f; do
        [ -n "$f" ] || continue
        echo "only in $a: ${f#./}"
        bad=$((bad + 1))
    done < <(LC_ALL=C comm -23 <(printf '%s\n' "$list_a") <(printf '%s\n' "$list_b"))
    while IFS= read -r f; do
        [ -n "$f" ] || continue
        echo "only in $b: ${f#./}"
        bad=$((bad + 1))
    done < <(LC_ALL=C comm -13 <(printf '%s\n' "$list_a") <(printf '%s\n' "$list_b"))
    while IFS= read -r f; do
        [ -n "$f" ] || continue
        n=$((n + 1))
        if ! cmp -s "$a/$f" "$b/$f"; then
            echo "differs: ${f#./}"
            bad=$((bad + 1))
        fi
    done < <(LC_ALL=C comm -12 <(printf '%s\n' "$list_a") <(printf '%s\n' "$list_b"))
    if [ "$bad" -ne 0 ]; then
        echo "$bad difference(s) ($n files in both); e.g. diff $a/FILE $b/FILE" >&2
        exit 1
    fi
    echo "identical: $n files"
}

# --- run ---------------------------------------------------------------------
# c NAME ARGS...: run `ARGS...` in OUTDIR; stdout to NAME.out, stderr to
# NAME.err, exit status to NAME.rc. Never stops the script.
c() {
    local name=$1
    shift
    if [ -e "$name.rc" ]; then
        echo "same-outputs.sh: duplicate command name $name" >&2
        exit 2
    fi
    local rc=0
    "$@" >"$name.out" 2>"$name.err" </dev/null || rc=$?
    echo "$rc" >"$name.rc"
}

# s NAME ARGS...: `snowroll ARGS...` once as CSV and once as JSON
# (NAME.csv.*, NAME.json.*).
s() {
    local name=$1
    shift
    c "$name.csv" snowroll "$@" --format csv
    c "$name.json" snowroll "$@" --format json
}

run_all() {
    # --- help and version (user-visible text; doc comments end up here) ---
    c version snowroll --version
    c help snowroll --help
    local sub
    for sub in simulate turns models paper sweep merge; do
        c "help-$sub" snowroll "$sub" --help
        c "help-short-$sub" snowroll "$sub" -h
    done
    c no-args snowroll
    c bad-subcommand snowroll frobnicate
    c bad-model snowroll simulate --model nosuch

    # --- models ---
    c models snowroll models
    c models-json snowroll models --format json

    # --- simulate: every model, CSV and JSON ---
    s sim-torque-cm-default simulate --model torque-cm
    s sim-torque-cm-dt simulate --model eq4 --t-end 20 --dt 0.5
    s sim-torque-contact simulate --model torque-contact --t-end 20 --dt 0.5
    s sim-energy simulate --model eq14 --alpha-deg 20 --snow-depth 0.02 --r0 0.15 --t-end 60 --dt 0.5
    s sim-energy-thin simulate --model energy-thin --x-end 50
    s sim-lagrangian-printed simulate --model lagrangian-printed --t-end 30
    s sim-quasi-circular simulate --model quasi-circular --t-end 30 --dt 1
    s sim-quasi-circular-lift simulate --model quasi-circular-lift --t-end 30
    s sim-loney-times simulate --model loney --times 1,10,100
    s sim-loney-steps simulate --model fn4 --t-end 10
    s sim-snowless simulate --model snowless --t-end 10 --dt 0.5
    s sim-snowless-v0 simulate --model snowless --v0 2 --alpha-deg 10 --g 1.62 --density 900 --length 2 --t-end 5
    s sim-stall simulate --model energy --alpha-deg 5 --snow-depth 0.05
    s sim-beyond-range simulate --model energy --snow-depth 0.2 --t-end 1 --dt 0.5
    s sim-tolerances simulate --model torque-cm --rtol 1e-6 --atol 1e-8 --t-end 10
    # the snowball
    s sim-ball-snowless simulate --model snowless --shape sphere --t-end 5
    s sim-ball-torque-cm simulate --model torque-cm --shape sphere --t-end 100 --dt 5
    s sim-ball-energy-swath simulate --model energy --shape sphere --swath-width 0.05 --t-end 30
    s sim-ball-loney simulate --model loney --shape sphere --times 1,10,100
    # losses and the ledger
    s sim-drag-terminal simulate --model snowless --drag-coefficient 1
    s sim-ball-drag-terminal simulate --model snowless --shape sphere --drag-coefficient 0.5 --air-density 1.0
    s sim-losses-energy simulate --model energy --drag-coefficient 1 --rolling-resistance 0.02 --compaction-energy 2 --t-end 30 --dt 1
    s sim-losses-torque-contact simulate --model torque-contact --rolling-resistance 0.05 --t-end 20
    s sim-losses-loney simulate --model loney --drag-coefficient 0.5 --times 1,5,10
    s sim-losses-ball simulate --model quasi-circular-lift --shape sphere --drag-coefficient 1 --compaction-energy 5 --t-end 20 --dt 2
    s sim-ledger simulate --model torque-cm --ledger --t-end 10 --dt 1
    s sim-ledger-terminal-tol simulate --model snowless --drag-coefficient 1 --terminal-tol 0 --t-end 50 --dt 5
    # contact forces: slip, hop
    s sim-mu-slip simulate --model torque-contact --mu 0.25
    s sim-mu-noslip simulate --model energy --mu 0.5 --t-end 10 --dt 1
    s sim-hop-stop simulate --model turns --alpha-deg 80 --turns 3
    s sim-hop-continue simulate --model turns --alpha-deg 80 --turns 3 --on-hop continue --dt 0.01
    # the turn models through simulate
    s sim-turns simulate --model turns --turns 5
    s sim-turns-dt simulate --model eq73 --turns 3 --dt 0.05
    s sim-turns-exact simulate --model turns-exact --turns 3 --dt 0.05 --ledger
    s sim-turns-charged simulate --model turns --collision charged --turns 3
    s sim-turns-pivot simulate --model turns --collision pivot --turns 3
    s sim-turns-exact-pivot simulate --model turns-exact --collision pivot --turns 20 --alpha-deg 60
    # limits
    s sim-max-steps simulate --model torque-cm --max-steps 50
    s sim-max-rows-stop simulate --model torque-cm --max-rows 7
    # refusals
    s sim-refuse-rows simulate --model torque-cm --dt 0.001 --max-rows 10
    s sim-refuse-turns-sphere simulate --model turns --shape sphere
    s sim-refuse-swath-cylinder simulate --model energy --swath-width 0.05
    s sim-refuse-loney-swath simulate --model loney --shape sphere --swath-width 0.05
    s sim-refuse-alpha simulate --model torque-cm --alpha-deg 95
    s sim-refuse-times simulate --model loney --times 10,1
    s sim-refuse-turns-circular simulate --model energy --turns 3
    s sim-refuse-turns-drag simulate --model turns --drag-coefficient 1

    # --- simulate -o and --config ---
    c sim-o-csv snowroll simulate --model eq14 --alpha-deg 20 --snow-depth 0.02 --r0 0.15 --t-end 60 --dt 0.5 --output run.csv
    c sim-o-json snowroll simulate --model eq14 --alpha-deg 20 --snow-depth 0.02 --r0 0.15 --t-end 60 --dt 0.5 --format json --output run.json
    c sim-o-losses-json snowroll simulate --model energy --drag-coefficient 1 --rolling-resistance 0.02 --t-end 20 --format json -o losses.json
    c turns-o snowroll turns --model turns --turns 20 --ledger -o turns.csv
    c sim-o-turns-csv snowroll simulate --model turns-exact --turns 4 --ledger --mu 0.3 -o turns-run.csv
    cat >scenario.toml <<'EOF'
# a scenario file: either spelling of the keys
model = "energy"
alpha-deg = 25
snow_depth = 0.02
r0 = 0.12
t_end = 30
dt = 1
rolling_resistance = 0.01
EOF
    cat >scenario-json.toml <<'EOF'
model = "torque-cm"
alpha_deg = 35
times = [1, 2, 4, 8]
format = "json"
EOF
    cat >scenario-bad.toml <<'EOF'
model = "energy"
no_such_key = 1
EOF
    c cfg-toml snowroll simulate --config scenario.toml
    c cfg-toml-override snowroll simulate --config scenario.toml --model torque-contact --alpha-deg 30
    c cfg-toml-json snowroll simulate --config scenario-json.toml
    c cfg-toml-bad snowroll simulate --config scenario-bad.toml
    c cfg-readback-csv snowroll simulate --config run.csv --output again.csv
    c cfg-readback-json snowroll simulate --config run.json --output again.json
    c cfg-readback-losses snowroll simulate --config losses.json
    c cfg-readback-turns snowroll simulate --config turns-run.csv
    c cfg-readback-override snowroll simulate --config run.json --t-end 10 --format csv
    cat >turns.toml <<'EOF2'
model = "turns-exact"
alpha_deg = 40
turns = 25
collision = "charged"
ledger = true
EOF2
    c cfg-turns-toml snowroll turns --config turns.toml
    c cfg-turns-toml-json snowroll turns --config turns.toml --format json --turns 10
    c cfg-turns-readback snowroll turns --config turns.csv --output turns-again.csv
    c cfg-turns-times-refused snowroll turns --config scenario-json.toml --model turns --turns 5
    c cfg-twice snowroll simulate --config run.csv --config run.json
    c cfg-own-output snowroll simulate --config run.csv --output run.csv

    # --- turns, CSV and JSON (summary on stderr) ---
    s turns-default turns --model turns
    s turns-200 turns --model turns --turns 200
    s turns-eq73-ledger turns --model eq73 --turns 50 --ledger
    s turns-exact turns --model turns-exact --turns 100
    s turns-exact-ledger turns --model turns-exact --turns 50 --ledger
    s turns-note turns --model turns --collision note --turns 30 --ledger
    s turns-charged turns --model turns --collision charged --turns 30 --ledger
    s turns-pivot turns --model turns --collision pivot --turns 30 --ledger
    s turns-exact-charged turns --model turns-exact --collision charged --turns 30
    s turns-exact-pivot turns --model turns-exact --collision pivot --turns 30 --alpha-deg 60
    s turns-pivot-continue turns --model turns --collision pivot --turns 30 --on-hop continue
    s turns-exact-pivot-continue turns --model turns-exact --collision pivot --turns 30 --alpha-deg 10 --on-hop continue
    s turns-stalled turns --model turns --collision charged --alpha-deg 2 --turns 30 --on-hop continue
    s turns-hop turns --model turns --alpha-deg 80 --turns 10
    s turns-hop-continue turns --model turns --alpha-deg 80 --turns 10 --on-hop continue
    s turns-slip turns --model turns --mu 0.22 --turns 30
    s turns-params turns --model turns-exact --alpha-deg 20 --snow-depth 0.005 --r0 0.2 --v0 1 --turns 40 --x-end 20
    s turns-refuse-circular turns --model energy
    s turns-refuse-sphere turns --model turns --shape sphere
    s turns-refuse-losses turns --model turns --rolling-resistance 0.01

    # --- sweep ---
    c sweep-csv snowroll sweep -q --model torque-cm,energy,turns,loney --alpha-deg 5:60:4 --snow-depth 0.001,0.01 --t-end 20 -o sweep.csv
    # without -q: the progress bar is drawn only on a terminal, so stderr is empty
    c sweep-noquiet snowroll sweep --model energy,turns --alpha-deg 5:60:4 -o sweep-noquiet.csv
    c sweep-stdout snowroll sweep -q --model torque-cm,eq21,snowless --alpha-deg 10,30 --t-end 5
    c sweep-ode snowroll sweep -q --model torque-cm,torque-contact,energy,energy-thin,lagrangian-printed,quasi-circular,quasi-circular-lift,loney,snowless --alpha-deg 5:60:3 --method ode -o sweep-ode.csv
    c sweep-auto snowroll sweep -q --model torque-cm,torque-contact,energy,energy-thin,lagrangian-printed,quasi-circular,quasi-circular-lift,loney,snowless --alpha-deg 5:60:3 -o sweep-auto.csv
    c sweep-settings snowroll sweep -q --model turns,turns-exact --alpha-deg 30,70 --mu 0.1,0.3 --on-hop stop,continue --collision note,charged,pivot --t-end 5 -o sweep-settings.csv
    c sweep-axes snowroll sweep -q --model energy,turns --r0 0.05,0.2 --g 9.81,1.62 --density 300,900 --length 0.5,2 --v0 0,1 --x-end 10,100 --rtol 1e-8,1e-10 --atol 1e-12 -o sweep-axes.csv
    c sweep-parquet snowroll sweep -q --model torque-cm,energy,turns --alpha-deg 5:60:4 --snow-depth 0.001,0.01 --t-end 20 -o sweep.parquet
    c sweep-parquet-format snowroll sweep -q --model energy --alpha-deg 10:50:5 --t-end 10 --format parquet -o sweep-pq.bin
    c sweep-parquet-stdout snowroll sweep -q --model energy --format parquet
    c sweep-config-csv snowroll sweep -q --config sweep.csv -o sweep-again.csv
    c sweep-config-parquet snowroll sweep -q --config sweep.parquet -o sweep-again.parquet
    c sweep-config-override snowroll sweep -q --config sweep.csv --t-end 10 -o sweep-override.csv
    cat >axes.toml <<'EOF'
model = ["energy", "eq4"]
alpha_deg = "5:60:6"
snow_depth = [0.001, 0.01]
EOF
    c sweep-grid snowroll sweep -q --grid axes.toml --t-end 30 -o sweep-grid.csv
    c sweep-grid-override snowroll sweep -q --grid axes.toml --model turns --t-end 5 -o sweep-grid-override.csv
    local i
    for i in 0 1 2; do
        c "sweep-shard-$i" snowroll sweep -q --grid axes.toml --t-end 30 --shard "$i/3" -o "shard-$i.csv"
    done
    c merge snowroll merge shard-2.csv shard-0.csv shard-1.csv -o merged.csv
    c merge-stdout snowroll merge shard-0.csv shard-1.csv shard-2.csv
    c merge-missing snowroll merge shard-0.csv shard-2.csv -o merged-missing.csv
    c merge-twice snowroll merge shard-0.csv shard-0.csv shard-1.csv shard-2.csv
    c sweep-shard-config snowroll sweep -q --config shard-1.csv -o shard-1-again.csv
    c sweep-plot snowroll sweep -q --model turns --alpha-deg 1:80:8 --snow-depth 0.002:0.02:4 --t-end 5 -o map-turns.csv --plot map-turns.svg
    c sweep-plot-mu snowroll sweep -q --model energy --alpha-deg 5:60:6 --mu 0.05:0.5:5 --t-end 5 -o map-mu.csv --plot map-mu.svg
    c sweep-plot-color snowroll sweep -q --model torque-cm --alpha-deg 5:60:6 --snow-depth 0.002:0.02:4 --t-end 10 -o map-v.csv --plot map-v.svg --plot-color v_m_s --plot-x snow_depth --plot-y alpha_deg
    c sweep-refuse-plot snowroll sweep -q --model energy,turns --alpha-deg 5:60:6 -o map-bad.csv --plot map-bad.svg
    c sweep-refuse-range snowroll sweep -q --model energy --alpha-deg 5:95:3
    c sweep-refuse-shard snowroll sweep -q --model energy --shard 3/3

    # --- paper (about 3 s) ---
    c paper snowroll paper --out paper --quiet --strict

    # --- Python ---
    # -c, not a file: a warning names its source file, and a path would differ
    # between runs (`<string>` does not).
    c python "$PYTHON" -I -c "$(cat "$tmp/api.py")"
}

write_python_snippet() {
    cat >"$1" <<'EOF'
# Every value the Python API returns, as text: repr() of each float (the
# shortest round-trip form, so equal text means equal bits).
import math
import sys

import numpy as np
import snowroll

out = open("python-api.txt", "w", encoding="utf-8")


def norm(x):
    """x with numpy scalars and arrays made plain, recursively."""
    if isinstance(x, np.ma.MaskedArray):
        return {"data": norm(np.ma.getdata(x)), "mask": norm(np.ma.getmaskarray(x))}
    if isinstance(x, np.ndarray):
        return [norm(v) for v in x.tolist()] if x.dtype != object else [norm(v) for v in x]
    if isinstance(x, np.generic):
        return norm(x.item())
    if isinstance(x, dict):
        return {str(k): norm(v) for k, v in sorted(x.items())}
    if isinstance(x, (list, tuple)):
        return [norm(v) for v in x]
    return x


def dump(label, result, meta):
    out.write(f"== {label}: {result!r} len={len(result)}\n")
    out.write(f"columns: {result.columns!r}\n")
    for name in result.columns:
        col = result[name]
        out.write(f"column {name} type={type(col).__name__} dtype={col.dtype} shape={col.shape}\n")
        if isinstance(col, np.ndarray) and col.dtype.kind in "fiub":
            out.write(f"  bytes {np.ascontiguousarray(np.ma.getdata(col)).tobytes().hex()}\n")
        out.write(f"  {norm(col)!r}\n")
    for attr in meta:
        out.write(f"{attr}: {norm(getattr(result, attr))!r}\n")


def refused(label, fn, *args, **kwargs):
    try:
        r = fn(*args, **kwargs)
        out.write(f"== {label}: not refused: {r!r}\n")
    except Exception as e:  # noqa: BLE001 -- the type and message are the output
        out.write(f"== {label}: {type(e).__name__}: {e}\n")


RES = ("stop", "params", "model", "equation", "version", "warnings")
TURN = ("summary",) + RES
SWEEP = ("grid_len", "shard", "version")

out.write(f"version {snowroll.__version__}\n")
out.write(f"__all__ {snowroll.__all__!r}\n")
out.write(f"models {norm(snowroll.models())!r}\n")
out.write(f"models(b, r0) {norm(snowroll.models(snow_depth=0.02, r0=0.2))!r}\n")

dump("simulate torque-cm", snowroll.simulate("torque-cm", alpha_deg=30, snow_depth=0.01, r0=0.1, t_end=20, dt=0.1), RES)
dump("simulate default", snowroll.simulate(), RES)
dump("simulate energy every step", snowroll.simulate("eq14", alpha_deg=20, snow_depth=0.02, r0=0.15, t_end=60), RES)
dump("simulate loney times", snowroll.simulate("loney", times=[1, 10, 100]), RES)
dump("simulate lagrangian-printed", snowroll.simulate("lagrangian-printed", t_end=30, dt=1), RES)
dump("simulate quasi-circular-lift", snowroll.simulate("quasi-circular-lift", t_end=30, x_end=100), RES)
dump("simulate snowless", snowroll.simulate("snowless", t_end=10, dt=0.5), RES)
dump("simulate ball", snowroll.simulate("torque-cm", shape="sphere", swath_width=None, t_end=50, dt=1), RES)
dump("simulate ball swath", snowroll.simulate("energy", shape="sphere", swath_width=0.05, t_end=20), RES)
dump("simulate losses", snowroll.simulate("energy", drag_coefficient=1, rolling_resistance=0.02, compaction_energy=2, t_end=30, dt=1), RES)
dump("simulate drag terminal", snowroll.simulate("snowless", drag_coefficient=1), RES)
dump("simulate ledger", snowroll.simulate("torque-cm", ledger=True, t_end=10, dt=1), RES)
dump("simulate slip", snowroll.simulate("torque-contact", mu=0.25), RES)
dump("simulate hop", snowroll.simulate("turns", alpha_deg=80, turns=3), RES)
dump("simulate hop continue", snowroll.simulate("turns", alpha_deg=80, turns=3, on_hop="continue", dt=0.01), RES)
dump("simulate turns-exact pivot", snowroll.simulate("turns-exact", collision="pivot", turns=5, dt=0.05), RES)
dump("simulate max_steps", snowroll.simulate("torque-cm", max_steps=50), RES)
dump("simulate beyond range", snowroll.simulate("energy", snow_depth=0.2, t_end=1, dt=0.5), RES)

dump("turns default", snowroll.turns(), TURN)
dump("turns 1000", snowroll.turns("turns", turns=1000), TURN)
dump("turns-exact ledger", snowroll.turns("turns-exact", turns=50, ledger=True), TURN)
dump("turns charged", snowroll.turns("turns", collision="charged", turns=30, ledger=True), TURN)
dump("turns pivot", snowroll.turns("turns", collision="pivot", turns=30), TURN)
dump("turns hop", snowroll.turns("turns", alpha_deg=80, turns=10), TURN)
dump("turns hop continue", snowroll.turns("turns", alpha_deg=80, turns=10, on_hop="continue"), TURN)
dump("turns slip", snowroll.turns("turns", mu=0.22, turns=30), TURN)

grid = {"model": "torque-cm,turns", "alpha_deg": "5:60:12", "snow_depth": [0.01, 0.02]}
dump("sweep", snowroll.sweep(grid), SWEEP)
dump("sweep ode", snowroll.sweep({"model": ["energy", "eq4", "loney"], "alpha_deg": [10, 30, 50]}, method="ode"), SWEEP)
dump("sweep settings", snowroll.sweep({"model": "turns,turns-exact", "alpha_deg": "30,70", "mu": [0.1, 0.3],
                                      "on_hop": "stop,continue", "collision": ["note", "charged", "pivot"], "t_end": 5}), SWEEP)
parts = [snowroll.sweep(grid, shard=(i, 3)) for i in (2, 0, 1)]
for i, p in zip((2, 0, 1), parts):
    dump(f"sweep shard {i}/3", p, SWEEP)
dump("sweep concat", snowroll.SweepResult.concat(parts), SWEEP)

refused("refuse sphere turns", snowroll.simulate, "turns", shape="sphere")
refused("refuse snow_depth", snowroll.simulate, "energy", snow_depth=-1)
refused("refuse type", snowroll.simulate, "energy", alpha_deg="thirty")
refused("refuse turns losses", snowroll.turns, "turns", drag_coefficient=1)
refused("refuse model", snowroll.simulate, "nosuch")
refused("refuse sweep grid", snowroll.sweep, {"model": "energy", "alpha_deg": "5:95:3"})
refused("refuse shard", snowroll.sweep, grid, shard=(3, 3))
out.close()
print("ok")
EOF
}

run() {
    local binary=$1 python=$2 outdir=$3
    [ -x "$binary" ] || { echo "not an executable: $binary" >&2; exit 2; }
    [ -x "$python" ] || command -v "$python" >/dev/null || { echo "not a python: $python" >&2; exit 2; }
    binary=$(cd "$(dirname "$binary")" && pwd)/$(basename "$binary")
    case $python in
        */*) python=$(cd "$(dirname "$python")" && pwd)/$(basename "$python") ;;
    esac
    if [ -e "$outdir" ] && [ -n "$(ls -A "$outdir")" ]; then
        echo "OUTDIR exists and is not empty: $outdir" >&2
        exit 2
    fi
    mkdir -p "$outdir"
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    mkdir "$tmp/bin"
    ln -s "$binary" "$tmp/bin/snowroll"
    write_python_snippet "$tmp/api.py"
    PYTHON=$python
    # A fixed environment: the program found as `snowroll`, C locale, no
    # inherited settings of the Python side or of rayon's thread count.
    export PATH="$tmp/bin:$PATH" LC_ALL=C LANG=C TZ=UTC COLUMNS=100 PYTHONHASHSEED=0
    unset PYTHONPATH PYTHONSTARTUP RUST_LOG NO_COLOR CLICOLOR CLICOLOR_FORCE RAYON_NUM_THREADS
    local start=$SECONDS
    # The list of commands is this file: a baseline made by another version of
    # it is stale, and the comparison says so (script.sha256 differs).
    local self_sum
    self_sum=$(sha256sum <"$self" | cut -d' ' -f1)
    cd "$outdir"
    echo "$self_sum" >script.sha256
    run_all
    local failed
    failed=$(grep -lv '^0$' ./*.rc | wc -l || true)
    echo "wrote $(find . -type f | wc -l) files in $outdir in $((SECONDS - start)) s ($failed commands exited non-zero, as recorded in their .rc)"
}

self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
[ $# -ge 1 ] || usage
case $1 in
    run)
        [ $# -eq 4 ] || usage
        run "$2" "$3" "$4"
        ;;
    compare)
        [ $# -eq 3 ] || usage
        compare "$2" "$3"
        ;;
    *) usage ;;
esac
