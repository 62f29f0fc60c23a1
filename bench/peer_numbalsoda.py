#!/usr/bin/env python3
"""The numbalsoda peer of snowroll's sweep benchmark (issue 12).

The same problem and grid as bench/peer_scipy.py --alphas: eq. (4) of the
note, x' = v, v' = (2/3) g sin(alpha) - 7 b v^2 / (6 pi r^2) with
pi r^2 = pi r0^2 + b x (eq. 8), b = 0.01 m, r0 = 0.1 m, g = 9.81 m/s^2, from
rest, t = 0..100 s, rtol 1e-10, atol 1e-12, integrated with numbalsoda's
DOP853 (Hairer's Fortran code called from a numba cfunc right-hand side, no
Python in the loop). The angles of `--alphas start:end:count` are passed
through the data pointer. Every trajectory of the grid is integrated in one
numba-compiled loop (the way numbalsoda is meant to be used for many runs);
the figure is the whole loop's CPU time divided by the number of
trajectories, after one warm-up pass that compiles it. The final speed of
the last angle is checked against Loney's closed form (fn. 4).

Install: bash bench/setup-peers.sh (numbalsoda builds from source with
gfortran and cmake). Usage:
    python bench/peer_numbalsoda.py --alphas 29:31:10000
The last line, per_trajectory_s=<seconds>, is read by bench/sweep_compare.sh.
"""

import argparse
import math
import time

import numba as nb
import numpy as np
from numbalsoda import dop853, lsoda_sig

B = 0.01  # snow depth, m
R0 = 0.1  # initial radius, m
G_ACC = 9.81  # m/s^2
T_END = 100.0  # s
RTOL = 1e-10
ATOL = 1e-12


@nb.cfunc(lsoda_sig)
def rhs(t, y, dy, p):
    """Eq. (4) with eq. (8); p[0] = g sin(alpha)."""
    area = math.pi * R0 * R0 + B * y[0]
    dy[0] = y[1]
    dy[1] = 2.0 / 3.0 * p[0] - 7.0 * B * y[1] * y[1] / (6.0 * area)


RHS = rhs.address


@nb.njit
def sweep(g_along, out):
    """Integrates every angle; out[i] = (x, v) at T_END."""
    y0 = np.zeros(2)
    t_eval = np.array([0.0, T_END])
    ok = True
    for i in range(g_along.shape[0]):
        data = np.array([g_along[i]])
        usol, success = dop853(RHS, y0, t_eval, data=data, rtol=RTOL, atol=ATOL)
        ok = ok and success
        out[i, 0] = usol[-1, 0]
        out[i, 1] = usol[-1, 1]
    return ok


def grid(spec):
    """The angles (deg) of the grid start:end:count, as snowroll computes them."""
    start, end, count = spec.split(":")
    start, end, count = float(start), float(end), int(count)
    if count < 1:
        raise SystemExit("--alphas: the count must be at least 1")
    return [
        end if k == count - 1 else start + (end - start) * (k / max(count - 1, 1))
        for k in range(count)
    ]


def loney_speed(x, g_along):
    s0 = math.pi * R0**2
    s = s0 + B * x
    k = -(2.0 * g_along / (5.0 * B)) * s0 ** (10.0 / 3.0)
    return math.sqrt(2.0 * g_along * s / (5.0 * B) + k * s ** (-7.0 / 3.0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--alphas", default="29:31:10000", help="grid start:end:count, degrees")
    args = parser.parse_args()
    alphas = grid(args.alphas)
    g_along = np.array([G_ACC * math.sin(math.radians(a)) for a in alphas])
    out = np.zeros((len(alphas), 2))
    sweep(g_along[:2], out[:2])  # compile
    cpu, wall = time.process_time(), time.perf_counter()
    ok = sweep(g_along, out)
    cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    if not ok:
        raise SystemExit("numbalsoda dop853 failed on some trajectory")
    x, v = out[-1]
    v_exact = loney_speed(x, g_along[-1])
    n = len(alphas)
    print(
        f"numbalsoda dop853 (numba {nb.__version__}), eq. (4): alpha {args.alphas} deg, b {B} m, "
        f"r0 {R0} m, from rest, t = 0..{T_END:g} s, rtol {RTOL:g}, atol {ATOL:g}, N = {n}"
    )
    print(f"final t = {T_END:g} s, x = {x:.15e} m, v = {v:.15e} m/s (alpha {alphas[-1]:.15g} deg)")
    print(
        f"closed form (fn. 4) at that x: v = {v_exact:.15e} m/s, "
        f"relative difference {abs(v - v_exact) / v_exact:.2e}"
    )
    print(
        f"per trajectory: CPU {cpu / n * 1e6:.2f} us, wall {wall / n * 1e6:.2f} us "
        f"(whole loop {cpu:.3f} s CPU)"
    )
    print(f"per_trajectory_s={cpu / n:e}")


if __name__ == "__main__":
    main()
