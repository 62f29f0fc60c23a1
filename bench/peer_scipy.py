#!/usr/bin/env python3
"""The SciPy peer of snowroll's speed benchmark (issue 2, "speed").

Integrates eq. (4) of McDonald's note, the log rolling down a snowy slope with
the torque taken about its centre,

    x' = v,   v' = (2/3) g sin(alpha) - 7 b v^2 / (6 pi r^2),   pi r^2 = pi r0^2 + b x  (eq. 8),

for alpha = 30 deg, b = 0.01 m, r0 = 0.1 m, g = 9.81 m/s^2, from rest, to
t = 100 s with scipy.integrate.solve_ivp(method="DOP853"), rtol 1e-10,
atol 1e-12, N times. The right-hand side is a plain Python function, as a
user would write it. Each trajectory is timed on its own, in wall-clock time
and in the CPU time of this thread; the figure is the median of the CPU
times, because on a shared machine a 5 ms run is often preempted and its
wall-clock time then counts other programs' work (a 20 us Rust run rarely
is, so its wall-clock median is already its CPU time). Wall-clock median,
mean (total/N) and minimum are printed beside it. The final speed is checked against Loney's closed form
(fn. 4), v^2 = 2G s/(5b) + K s^(-7/3), s = pi r^2, K = -(2G/(5b)) (pi r0^2)^(10/3),
so that both programs can be seen to solve the same problem.

Usage: python3 bench/peer_scipy.py [--n 1000]
The last line, per_trajectory_s=<CPU-time median>, is read by bench/compare.sh.

Sweep mode (issue 12): python3 bench/peer_scipy.py --alphas 29:31:10000 [--n 1000]
integrates the same problem at the angles of `snowroll sweep --alpha-deg
29:31:10000` (start:end:count, both ends included), N of them evenly picked
from that grid when N is smaller, and prints the same figures;
bench/sweep_compare.sh reads them.
"""

import argparse
import math
import statistics
import time

import numpy as np
from scipy.integrate import solve_ivp

ALPHA = math.radians(30.0)  # slope angle, rad
B = 0.01  # snow depth, m
R0 = 0.1  # initial radius, m
G_ACC = 9.81  # gravitational acceleration, m/s^2
T_END = 100.0  # s
RTOL = 1e-10
ATOL = 1e-12
WARM_UP_RUNS = 3  # untimed runs first (imports, caches)


def rhs(t, y, alpha=ALPHA):
    """Eq. (4) with the radius of eq. (8)."""
    x, v = y
    area = np.pi * R0**2 + B * x  # pi r^2
    a = 2.0 / 3.0 * G_ACC * np.sin(alpha) - 7.0 * B * v**2 / (6.0 * area)
    return [v, a]


def loney_speed(x, alpha=ALPHA):
    """Loney's closed form of eq. (4) from rest (fn. 4)."""
    g_along = G_ACC * math.sin(alpha)
    s0 = math.pi * R0**2
    s = s0 + B * x
    k = -(2.0 * g_along / (5.0 * B)) * s0 ** (10.0 / 3.0)
    return math.sqrt(2.0 * g_along * s / (5.0 * B) + k * s ** (-7.0 / 3.0))


def one_trajectory(alpha=ALPHA):
    return solve_ivp(
        rhs, (0.0, T_END), [0.0, 0.0], method="DOP853", rtol=RTOL, atol=ATOL, args=(alpha,)
    )


def grid_angles(spec, n):
    """N angles (rad) picked evenly from the grid start:end:count (degrees)."""
    start, end, count = spec.split(":")
    start, end, count = float(start), float(end), int(count)
    if count < 1:
        raise SystemExit("--alphas: the count must be at least 1")
    picks = range(count) if n >= count else (round(k * (count - 1) / max(n - 1, 1)) for k in range(n))
    return [
        math.radians(end if k == count - 1 else start + (end - start) * (k / max(count - 1, 1)))
        for k in picks
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1000, help="number of trajectories (default 1000)")
    parser.add_argument(
        "--alphas", help="sweep mode: the angles of this grid start:end:count, in degrees"
    )
    args = parser.parse_args()
    n = args.n
    if n < 1:
        parser.error("--n must be at least 1")
    alphas = grid_angles(args.alphas, n) if args.alphas else [ALPHA] * n
    n = len(alphas)

    for _ in range(WARM_UP_RUNS):
        one_trajectory()
    times = []
    cpu_times = []
    total = time.perf_counter()
    for alpha in alphas:
        start, start_cpu = time.perf_counter(), time.thread_time()
        sol = one_trajectory(alpha)
        times.append(time.perf_counter() - start)
        cpu_times.append(time.thread_time() - start_cpu)
    total = time.perf_counter() - total
    if not sol.success:
        raise SystemExit(f"solve_ivp failed: {sol.message}")

    x, v = sol.y[0, -1], sol.y[1, -1]
    v_exact = loney_speed(x, alphas[-1])
    per_trajectory = statistics.median(cpu_times)
    angles = f"alpha {args.alphas} deg (grid)" if args.alphas else "alpha 30 deg"
    print(
        f"scipy {__import__('scipy').__version__} solve_ivp DOP853, eq. (4): {angles}, b 0.01 m, "
        f"r0 0.1 m, from rest, t = 0..{T_END:g} s, rtol {RTOL:g}, atol {ATOL:g}, N = {n}"
    )
    print(f"steps {len(sol.t) - 1} accepted, {sol.nfev} RHS evaluations per trajectory")
    print(
        f"final t = {sol.t[-1]:g} s, x = {x:.15e} m, v = {v:.15e} m/s "
        f"(alpha {math.degrees(alphas[-1]):.15g} deg)"
    )
    print(
        f"closed form (fn. 4) at that x: v = {v_exact:.15e} m/s, "
        f"relative difference {abs(v - v_exact) / v_exact:.2e}"
    )
    print(
        f"per trajectory: CPU time median {per_trajectory * 1e3:.3f} ms; wall clock: median "
        f"{statistics.median(times) * 1e3:.3f} ms, mean (total/N) {total / n * 1e3:.3f} ms, "
        f"min {min(times) * 1e3:.3f} ms"
    )
    print(f"per_trajectory_s={per_trajectory:e}")


if __name__ == "__main__":
    main()
