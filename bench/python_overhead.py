"""What a Python call adds to the library's own time (issue 37, item 3),
measured in one run, rounds alternating:

(1) ``snowroll.simulate("torque-cm", t_end=100, times=[100])`` from Python
    against the same run through the Rust API (the example ``one_call``:
    the keywords as parameter-table values over the defaults, the validated
    scenario, the run into an in-memory sink), each call timed on its own,
    medians per round; and the same with the first column read
    (``r.friction_ratio``, the masked column made on first read);
(2) ``snowroll.turns(turns=100)`` against ``one_call turns 100``;
(3) ``snowroll.sweep`` over a numpy array of ``N_SWEEP`` slopes (the
    closed-form path) against the CLI's ``snowroll sweep`` of the same grid
    written to a CSV file (whole process): CPU time a row, both.

Usage (bench/python_overhead.sh builds everything and runs this):
    python bench/python_overhead.py ONE_CALL SNOWROLL_CLI [ROUNDS] [N_SWEEP]
with ``snowroll`` importable (a release wheel). Prints each round and the
medians over rounds.
"""

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import snowroll


def rust_median(one_call, args, n):
    """The example's median time a call, s."""
    out = subprocess.run(
        [one_call, *args, "--n", str(n)], check=True, capture_output=True, text=True
    ).stdout
    fields = dict(kv.split("=") for kv in out.strip().splitlines()[-1].split())
    return float(fields["median_s"])


def python_median(call, n):
    """The median time of ``call()``, s, each call timed on its own."""
    for _ in range(200):
        call()
    times = []
    clock = time.perf_counter_ns
    for _ in range(n):
        t0 = clock()
        call()
        times.append(clock() - t0)
    return statistics.median(times) * 1e-9


def cpu_of_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def sweep_rows(cli, n, out_dir):
    """CPU seconds a row: snowroll.sweep from a numpy array (this process,
    every thread), and the CLI's whole process writing its CSV."""
    grid = {
        "model": "torque-cm",
        "alpha_deg": np.linspace(29.0, 31.0, n),
        "snow_depth": 0.01,
        "r0": 0.1,
        "t_end": 100.0,
        "rtol": 1e-10,
        "atol": 1e-12,
    }
    t0 = time.process_time()
    r = snowroll.sweep(grid)
    py = (time.process_time() - t0) / n
    c0 = cpu_of_children()
    subprocess.run(
        [cli, "sweep", "--model", "torque-cm", "--alpha-deg", f"29:31:{n}",
         "--snow-depth", "0.01", "--r0", "0.1", "--t-end", "100",
         "--rtol", "1e-10", "--atol", "1e-12",
         "--output", os.path.join(out_dir, "sweep.csv")],
        check=True, stdout=subprocess.DEVNULL,
    )
    cli_row = (cpu_of_children() - c0) / n
    assert len(r) == n
    return py, cli_row


def main():
    one_call, cli = sys.argv[1], sys.argv[2]
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    n_sweep = int(sys.argv[4]) if len(sys.argv) > 4 else 100_000

    def sim():
        return snowroll.simulate("torque-cm", t_end=100, times=[100])

    def sim_read():
        return sim().friction_ratio

    def turns():
        return snowroll.turns(turns=100)

    # The same run: Python's final speed equals the Rust example's (its
    # output line) to the bit; checked once here.
    v = sim().v_m_s[-1]
    line = subprocess.run([one_call, "--n", "1"], check=True, capture_output=True,
                          text=True).stdout.splitlines()[0]
    assert f"last v = {float(v)!r} m/s" in line, (v, line)

    rows = {k: [] for k in ("sim", "sim_rust", "sim_read", "turns", "turns_rust", "sweep_py", "sweep_cli")}
    with tempfile.TemporaryDirectory() as out_dir:
        for k in range(rounds):
            rows["sim_rust"].append(rust_median(one_call, ["simulate"], 20_000))
            rows["sim"].append(python_median(sim, 20_000))
            rows["sim_read"].append(python_median(sim_read, 20_000))
            rows["turns_rust"].append(rust_median(one_call, ["turns", "100"], 2_000))
            rows["turns"].append(python_median(turns, 2_000))
            py, cli_row = sweep_rows(cli, n_sweep, out_dir)
            rows["sweep_py"].append(py)
            rows["sweep_cli"].append(cli_row)
            print(
                f"round {k}: simulate rust {rows['sim_rust'][-1] * 1e6:.2f} us, python "
                f"{rows['sim'][-1] * 1e6:.2f} us (+{(rows['sim'][-1] - rows['sim_rust'][-1]) * 1e6:.2f}), "
                f"with a column read {rows['sim_read'][-1] * 1e6:.2f} us; "
                f"turns(100) rust {rows['turns_rust'][-1] * 1e6:.1f} us, python "
                f"{rows['turns'][-1] * 1e6:.1f} us (+{(rows['turns'][-1] - rows['turns_rust'][-1]) * 1e6:.2f}); "
                f"sweep CPU a row: python {py * 1e6:.3f} us, CLI {cli_row * 1e6:.3f} us",
                flush=True,
            )
    med = {k: statistics.median(v) * 1e6 for k, v in rows.items()}
    over = statistics.median(p - r for p, r in zip(rows["sim"], rows["sim_rust"])) * 1e6
    over_read = statistics.median(p - r for p, r in zip(rows["sim_read"], rows["sim_rust"])) * 1e6
    over_turns = statistics.median(p - r for p, r in zip(rows["turns"], rows["turns_rust"])) * 1e6
    ratio = statistics.median(p / c for p, c in zip(rows["sweep_py"], rows["sweep_cli"]))
    print(f"median of {rounds} rounds (load average {os.getloadavg()[0]:.2f}):")
    print(f"  simulate: rust {med['sim_rust']:.2f} us, python {med['sim']:.2f} us, "
          f"python over rust {over:.2f} us a call ({over_read:.2f} us with a column read)")
    print(f"  turns(100): rust {med['turns_rust']:.1f} us, python {med['turns']:.1f} us, "
          f"python over rust {over_turns:.2f} us a call")
    print(f"  sweep of {n_sweep} rows, CPU a row: python {med['sweep_py']:.3f} us, "
          f"CLI {med['sweep_cli']:.3f} us, python/CLI {ratio:.2f}")


if __name__ == "__main__":
    main()
