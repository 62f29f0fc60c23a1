#!/usr/bin/env bash
# examples/slurm-sweep.sh on a real Slurm cluster (issue 24):
#
#   bash scripts/test-slurm.sh [SNOWROLL]      # default: $SNOWROLL_CLI, else target/release/snowroll
#
# Installs Debian's slurm-wlm and munge when missing (.ci/install-slurm.sh;
# needs root or sudo), starts a one-node cluster on this machine (munged,
# slurmctld and slurmd, all with a generated configuration in a temporary
# directory: nothing under /etc is used or changed), then
#   1. submits the example as a job array of 4 tasks (`sbatch --array=0-3`),
#      waits for them, merges, and checks that the merged file is the same
#      bytes as the sweep run in one process;
#   2. runs a slower grid as 2 tasks, cancels one mid-run (`scancel`) once its
#      FILE.partial holds rows, resubmits that array index (the example passes
#      --resume, and snowroll refuses a partial file without it), merges and
#      checks again.
# "The same bytes" means the whole file, `#` header included: merge records
# the command line of the one-process sweep its shards make up, so the
# reference is that sweep written to the merged file's path (OUT=. in the
# merge's directory, --output ./sweep.csv in the reference's). The cluster is
# torn down on exit, also on failure. Skips (exit 0, saying why) only without root and sudo, or
# without apt-get.
#
# A busy machine cannot break it (issue 33, item 6): the cluster's two ports
# are picked free at run time (another cluster on the machine, or a second
# copy of this test, had made the controller die with "Address already in
# use" on the fixed 6817/6818), and picked again if a daemon still finds its
# port taken; its state, spool, munge socket and logs are in a private
# temporary directory; every wait is bounded by the clock (a minute at most,
# each Slurm command under `timeout`), and a daemon that dies ends the wait
# at once; on failure the daemons' logs are printed.
#
#   bash scripts/test-slurm.sh --pair [SNOWROLL]   # two copies at once, each its own cluster
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
started=$SECONDS

# Two copies of this test at once (scripts/test.sh runs it so): both must
# pass, each on its own cluster; their outputs are shown one after the other.
if [ "${1:-}" = --pair ]; then
    shift
    if [ "$(id -u)" -eq 0 ] || sudo -n true 2>/dev/null; then
        command -v apt-get >/dev/null 2>&1 && bash .ci/install-slurm.sh
    fi
    logs=$(mktemp -d)
    trap 'rm -rf "$logs"' EXIT
    bash "$0" "$@" >"$logs/1" 2>&1 &
    first=$!
    bash "$0" "$@" >"$logs/2" 2>&1 &
    second=$!
    status=0
    wait "$first" || status=1
    wait "$second" || status=1
    sed 's/^/[copy 1] /' "$logs/1"
    sed 's/^/[copy 2] /' "$logs/2"
    if [ "$status" -ne 0 ]; then
        echo "test-slurm: FAIL: of two copies run at once, one or both failed (above)" >&2
        exit 1
    fi
    echo "test-slurm: two copies at once passed, in $((SECONDS - started)) s"
    exit 0
fi

cli=${1:-${SNOWROLL_CLI:-$root/${CARGO_TARGET_DIR:-target}/release/snowroll}}
case $cli in
    /*) ;;
    *) cli=$root/$cli ;;
esac
if [ ! -x "$cli" ]; then
    echo "test-slurm: FAIL: no snowroll program at $cli (build it, or pass its path)" >&2
    exit 1
fi

if [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
    echo "test-slurm: SKIP: installing and running Slurm needs root or passwordless sudo"
    exit 0
fi
if ! command -v apt-get >/dev/null 2>&1; then
    echo "test-slurm: SKIP: no apt-get to install Debian's slurm-wlm and munge"
    exit 0
fi
bash .ci/install-slurm.sh
export PATH=$PATH:/usr/sbin:/sbin
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi

# The grid of the array test: 80,000 trajectories through the ODE solver,
# about a second of CPU in all on an idle machine (13 us each). The grid of
# the cancel test: four times the slopes at rtol 1e-12, 320,000 trajectories
# of about 9 us each (the Taylor-series steps made them 3x faster), so each
# of its two tasks runs for about 1.5 s on an idle CPU, long enough to cancel
# it mid-run: with 80,000 trajectories a task of one of two copies run at
# once finished (in 0.4 s) before scancel reached it. Its rows go to
# FILE.partial 200 at a time.
export GRID_FLAGS="--model torque-cm,torque-contact,energy,quasi-circular --alpha-deg 1:89:200 --snow-depth 0.0001:0.1:100 --t-end 100 --method ode"
cancel_grid="--model torque-cm,torque-contact,energy,quasi-circular --alpha-deg 1:89:800 --snow-depth 0.0001:0.1:100 --t-end 100 --method ode --rtol 1e-12 --chunk-rows 200"
export SNOWROLL=$cli

tmp=$(mktemp -d /tmp/snowroll-slurm.XXXXXX)
chmod 755 "$tmp"
pids=()

# The slowest a Slurm command may answer (a controller that is down makes
# sinfo and squeue retry for tens of seconds), and the longest any wait of
# this test lasts.
answer=10
minute=60

# Runs a Slurm command, bounded by $answer seconds.
bounded() { timeout "$answer" "$@"; }

# Stops the daemons, newest first, each by the id it was started with.
stop_daemons() {
    local k pid
    for ((k = ${#pids[@]} - 1; k >= 0; k--)); do
        $sudo kill "${pids[k]}" 2>/dev/null
    done
    for pid in "${pids[@]}"; do
        for _ in $(seq 50); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.2
        done
        if kill -0 "$pid" 2>/dev/null; then
            echo "test-slurm: process $pid did not stop on SIGTERM, killing it" >&2
            $sudo kill -9 "$pid" 2>/dev/null
        fi
        wait "$pid" 2>/dev/null
    done
    pids=()
}

# The daemons' logs and the tasks' outputs, to stderr (the logs are root's
# when the daemons ran under sudo).
print_logs() {
    local f
    for f in "$tmp"/*.log "$tmp"/*.out "$tmp"/out*/slurm-*.out; do
        [ -e "$f" ] || continue
        echo "---- $f (last 40 lines)" >&2
        $sudo tail -n 40 "$f" >&2
    done
}

teardown() {
    local status=$?
    set +e
    if [ -n "${SLURM_CONF:-}" ] && [ -e "$tmp/slurmctld.started" ]; then
        bounded scancel --quiet --user="$(id -un)" 2>/dev/null
        for _ in $(seq 20); do
            [ -z "$(bounded squeue -h 2>/dev/null)" ] && break
            sleep 0.5
        done
    fi
    stop_daemons
    if [ "$status" -ne 0 ]; then
        echo "test-slurm: FAIL (exit $status); the logs:" >&2
        print_logs
    fi
    $sudo rm -rf "$tmp"
    echo "test-slurm: took $((SECONDS - started)) s"
    exit "$status"
}
trap teardown EXIT
trap 'exit 130' INT TERM

# Fails naming $1 unless every daemon started is still running.
daemons_alive() {
    local pid
    for pid in "${pids[@]}"; do
        if ! kill -0 "$pid" 2>/dev/null; then
            echo "test-slurm: a daemon (process $pid) has exited while waiting for $1" >&2
            return 1
        fi
    done
}

# Runs `$3...` every 0.2 s until it succeeds; fails when $1 seconds have
# passed or a daemon has died (waiting for $2).
wait_for() {
    local limit=$1 what=$2 end=$((SECONDS + $1))
    shift 2
    until "$@"; do
        daemons_alive "$what" || return 1
        if [ "$SECONDS" -ge "$end" ]; then
            echo "test-slurm: $what: not there after $limit s" >&2
            return 1
        fi
        sleep 0.2
    done
}

# N TCP ports free on every address at this moment, all different: bound to
# port 0 together, so the kernel picks them, then released for the daemons.
free_ports() {
    python3 -c '
import socket, sys
held = []
for _ in range(int(sys.argv[1])):
    s = socket.socket()
    s.bind(("", 0))
    held.append(s)
print(" ".join(str(s.getsockname()[1]) for s in held))
' "$1"
}

# munge: a fresh key and its own socket, in the temporary directory.
mkdir -m 700 "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 600 "$tmp/munge/munge.key"
$sudo munged --foreground --force --key-file="$tmp/munge/munge.key" \
    --socket="$tmp/munge/munge.socket" --pid-file="$tmp/munge/munged.pid" \
    --seed-file="$tmp/munge/munged.seed" --log-file="$tmp/munged.log" \
    >"$tmp/munged.out" 2>&1 &
pids+=($!)
munge_pid=$!
wait_for 10 "munged's socket" test -S "$tmp/munge/munge.socket"

node=$(hostname -s)
user=$(id -un)
mkdir -p "$tmp/state" "$tmp/spool"

# Writes slurm.conf with the controller's port $1 and the node's $2.
write_conf() {
    cat >"$tmp/slurm.conf" <<CONF
# Generated by scripts/test-slurm.sh: one node, no cgroups, no accounting,
# ports picked free at run time.
ClusterName=snowrolltest
SlurmctldHost=localhost
SlurmctldPort=$1
SlurmdPort=$2
SlurmUser=$user
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
MinJobAge=600
KillWait=5
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
}
export SLURM_CONF=$tmp/slurm.conf

node_idle() {
    [ "$(bounded sinfo -h -n "$node" -o %T 2>/dev/null)" = idle ]
}

# The controller and the node's daemon on ports free a moment ago; ready
# when the node is idle. A port taken in between (by another cluster's
# daemon) makes a daemon exit with "Address already in use": the daemons are
# then started again on other ports, up to three times.
for attempt in 1 2 3; do
    read -r ctld_port slurmd_port <<<"$(free_ports 2)"
    write_conf "$ctld_port" "$slurmd_port"
    rm -f "$tmp"/slurmctld.* "$tmp"/slurmd.*
    $sudo slurmctld -D -f "$SLURM_CONF" >"$tmp/slurmctld.out" 2>&1 &
    pids+=($!)
    touch "$tmp/slurmctld.started"
    $sudo slurmd -D -f "$SLURM_CONF" >"$tmp/slurmd.out" 2>&1 &
    pids+=($!)
    if wait_for "$minute" "the node to come up (ports $ctld_port, $slurmd_port)" node_idle; then
        break
    fi
    if [ "$attempt" -lt 3 ] && $sudo grep -qs "Address already in use" "$tmp"/slurm*.log "$tmp"/slurm*.out; then
        echo "test-slurm: a port was taken in the meantime; again on other ports" >&2
        # Only the Slurm daemons: munged (the first) keeps running.
        pids=("${pids[@]:1}")
        stop_daemons
        pids=("$munge_pid")
        continue
    fi
    exit 1
done
echo "test-slurm: one-node cluster up ($(bounded sinfo -V), node $node, 2 CPUs, ports $ctld_port and $slurmd_port)"

# Waits until no task of job $1 is pending or running (at most $2 s), then
# checks that every task listed in $3 ended in state $4.
job_gone() { [ -z "$(bounded squeue -h -j "$1" 2>/dev/null)" ]; }
wait_job() {
    local job=$1 timeout=$2 tasks=$3 want=$4 t got
    wait_for "$timeout" "job $job to end" job_gone "$job" || exit 1
    for t in $tasks; do
        got=$(bounded scontrol show job "${job}_$t" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -1)
        if [ "$got" != "$want" ]; then
            echo "test-slurm: task ${job}_$t ended $got, expected $want" >&2
            exit 1
        fi
    done
}

# Checks that two sweep files are the same bytes.
same_bytes() {
    if ! cmp "$1" "$2" >&2; then
        echo "test-slurm: $1 and $2 differ:" >&2
        diff "$1" "$2" | head -5 >&2 || true
        exit 1
    fi
    echo "test-slurm: $1 = $2 ($(($(grep -vc '^#' "$1") - 1)) rows, every byte)"
}

# The references: each grid whole, in one process, written to ./sweep.csv
# in a directory of its own, the path the merges below write to.
mkdir "$tmp/whole" "$tmp/whole-cancel"
# shellcheck disable=SC2086
(cd "$tmp/whole" && "$cli" sweep $GRID_FLAGS --quiet --output ./sweep.csv)
# shellcheck disable=SC2086
(cd "$tmp/whole-cancel" && "$cli" sweep $cancel_grid --quiet --output ./sweep.csv)

# 1. Four tasks, one CPU each (two at a time on the two CPUs).
mkdir "$tmp/out4"
job=$(cd "$tmp/out4" && SHARDS=4 OUT="$tmp/out4" bounded sbatch --parsable --array=0-3 \
    --cpus-per-task=1 "$root/examples/slurm-sweep.sh")
echo "test-slurm: submitted job array $job (4 tasks)"
wait_job "$job" "$minute" "0 1 2 3" COMPLETED
(cd "$tmp/out4" && SHARDS=4 OUT=. bash "$root/examples/slurm-sweep.sh" merge)
same_bytes "$tmp/out4/sweep.csv" "$tmp/whole/sweep.csv"

# 2. Two tasks of the cancel grid; task 1 cancelled once its partial file holds rows, then
# resubmitted.
mkdir "$tmp/out2"
export GRID_FLAGS=$cancel_grid
job=$(cd "$tmp/out2" && SHARDS=2 OUT="$tmp/out2" bounded sbatch --parsable --array=0-1 \
    --cpus-per-task=1 "$root/examples/slurm-sweep.sh")
echo "test-slurm: submitted job array $job (2 tasks)"
partial=$tmp/out2/sweep-1.csv.partial
# Looked at every 0.02 s (not wait_for's 0.2 s), to cancel the task early in its run.
rows=0
end=$((SECONDS + minute))
while [ "$SECONDS" -lt "$end" ]; do
    [ -e "$partial" ] && rows=$(grep -vc '^#' "$partial" || true)
    [ "$rows" -gt 1 ] && break
    daemons_alive "rows in $partial" || exit 1
    sleep 0.02
done
if [ "$rows" -le 1 ]; then
    echo "test-slurm: task ${job}_1 wrote no rows to $partial in $minute s" >&2
    exit 1
fi
bounded scancel "${job}_1"
wait_job "$job" "$minute" "0" COMPLETED
wait_job "$job" "$minute" "1" CANCELLED
if [ -e "$tmp/out2/sweep-1.csv" ] || [ ! -e "$partial" ]; then
    echo "test-slurm: task ${job}_1 finished before it was cancelled (make its shard larger)" >&2
    exit 1
fi
left=$(grep -vc '^#' "$partial")
echo "test-slurm: cancelled ${job}_1 with $((left - 1)) of 160000 rows in its partial file"
job=$(cd "$tmp/out2" && SHARDS=2 OUT="$tmp/out2" bounded sbatch --parsable --array=1 \
    --cpus-per-task=1 "$root/examples/slurm-sweep.sh")
echo "test-slurm: resubmitted task 1 as job $job"
wait_job "$job" "$minute" "1" COMPLETED
[ ! -e "$partial" ] || { echo "test-slurm: $partial left behind" >&2; exit 1; }
(cd "$tmp/out2" && SHARDS=2 OUT=. bash "$root/examples/slurm-sweep.sh" merge)
same_bytes "$tmp/out2/sweep.csv" "$tmp/whole-cancel/sweep.csv"

echo "test-slurm: 2 passed, 0 failed"

# Timings for bench/README.md (not a test): SLURM_BENCH="GRID FLAGS" runs
# that grid in one process with 1, 2 and 4 threads, then as 1, 2 and 4 tasks
# of 1 CPU each (the node has 2 CPUs: Slurm runs the 4 tasks two at a time),
# then 16 tasks of a 16-point grid (the fixed cost of a task); it times each
# task array from sbatch to the last task's end, and its merge, and prints
# the load average beside each figure (the machine may be shared).
elapsed() { awk "BEGIN { printf \"%.2f\", $(date +%s.%N) - $1 }"; }
load() { cut -d' ' -f1-3 /proc/loadavg; }
bench_process() { # $1 threads, $2 grid flags
    local TIMEFORMAT="%R s wall, %U s user + %S s system" took
    # shellcheck disable=SC2086
    took=$( { time RAYON_NUM_THREADS=$1 "$cli" sweep $2 --quiet \
        --output "$tmp/bench-process.csv" 2>"$tmp/bench-process.err"; } 2>&1)
    echo "test-slurm bench: one process, $1 thread(s): $took (load $(load))"
    rm -f "$tmp/bench-process.csv"
}
bench_array() { # $1 name, $2 shards, $3 grid flags
    local dir=$tmp/bench-$1 t0 job
    mkdir "$dir"
    t0=$(date +%s.%N)
    job=$(cd "$dir" && GRID_FLAGS=$3 SHARDS=$2 OUT=$dir sbatch --parsable \
        --array=0-$(($2 - 1)) --cpus-per-task=1 "$root/examples/slurm-sweep.sh")
    wait_job "$job" 3600 "$(seq -s ' ' 0 $(($2 - 1)))" COMPLETED
    echo "test-slurm bench: $1: $2 tasks, $(elapsed "$t0") s from sbatch to the end (load $(load))"
    t0=$(date +%s.%N)
    GRID_FLAGS=$3 SHARDS=$2 OUT=$dir bash examples/slurm-sweep.sh merge
    echo "test-slurm bench: $1: merge $(elapsed "$t0") s for $(grep -vc '^#' "$dir/sweep.csv") lines (load $(load))"
    rm -f "$dir"/sweep*.csv
}
if [ -n "${SLURM_BENCH:-}" ]; then
    for threads in 1 2 4; do bench_process "$threads" "$SLURM_BENCH"; done
    bench_array one 1 "$SLURM_BENCH"
    bench_array two 2 "$SLURM_BENCH"
    bench_array four 4 "$SLURM_BENCH"
    bench_array tiny 16 "--model torque-cm --alpha-deg 1:89:16 --t-end 100"
fi
