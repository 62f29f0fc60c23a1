#!/usr/bin/env python3
"""Independent reference for the turn-by-turn model (docs/turn-model.md), without an ODE solver.

Both in-turn variants conserve their own energy I(θ)θ̇²/2 + V(θ) during a turn, so the speed at
the end of each turn follows from the energy integral, the turn's duration from
t = ∫ dθ/θ̇(θ) (scipy.integrate.quad, θ = w² near a start from rest), and the next turn's start
from the collision rule v' = v (r_{k+1}² + 2 r_k²)/(3 r_k r_{k+1}) (eq. 89, corrected indices).

Writes turns_reference.csv beside this file: selected turns of both variants for the default
scenario (α = 30°, b = 0.01 m, r0 = 0.1 m, g = 9.81 m/s², ρ = 400 kg/m³, l = 1 m, from rest).
Run: python3 make_turns_reference.py   (needs numpy, scipy)
"""
import csv
import math
import os

from scipy.integrate import quad

ALPHA = math.radians(30.0)
B, R0, G0, RHO, L = 0.01, 0.1, 9.81, 400.0, 1.0
GS, GC = G0 * math.sin(ALPHA), G0 * math.cos(ALPHA)
TURNS = 2000
KEEP = {0, 1, 2, 3, 5, 10, 20, 50, 100, 200, 500, 1000, 1999}


def paper_turn(r):
    """I(θ), V(θ) per unit m_k for eq. (73)/(76) (O(b/r))."""
    def inertia(th):
        return 1.5 * r * r + (2 * B * r / math.pi) * (th - math.sin(th))

    def potential(th):
        return (-r * th * GS - (B / math.pi) * (th * th / 2 - 1 + math.cos(th)) * GS
                + (B / math.pi) * (th - math.sin(th)) * GC)
    return inertia, potential


def exact_turn(r):
    """I_C(θ), V(θ) per unit m_k for the disk plus annular sector, no truncation in b/r."""
    d2, d3, d4 = (r + B) ** 2 - r ** 2, (r + B) ** 3 - r ** 3, (r + B) ** 4 - r ** 4
    mk = math.pi * RHO * L * r * r

    def inertia(th):
        ic = 1.5 * math.pi * RHO * L * r ** 4 + RHO * L * th * (r * r * d2 / 2 + d4 / 4) \
            - (2.0 / 3.0) * RHO * L * r * d3 * math.sin(th)
        return ic / mk

    def potential(th):
        ms = RHO * L * th * d2 / 2
        x = r * th
        normal = ms * r - RHO * L * d3 * math.sin(th) / 3 + ms * B / 2
        along = (mk + ms / 2) * x - RHO * L * d3 * (1 - math.cos(th)) / 3
        return (GC * normal - GS * along) / mk
    return inertia, potential


def run(variant):
    rows = []
    t, v_start = 0.0, 0.0
    for k in range(TURNS):
        r, r_next = R0 + k * B, R0 + (k + 1) * B
        inertia, potential = variant(r)
        e0 = inertia(0.0) * (v_start / r) ** 2 / 2

        def omega(th):
            return math.sqrt(max(2 * (e0 - potential(th)) / inertia(th), 0.0))

        if v_start == 0.0:
            # θ = w²: dt = 2w dw / θ̇(w²), finite at w = 0.
            def f(w):
                return 2 * w / omega(w * w) if w > 0 else 2 / math.sqrt(2 * (-(potential(1e-12) / 1e-12)) / inertia(0.0))
            dt, _ = quad(f, 0.0, math.sqrt(2 * math.pi), epsabs=0, epsrel=1e-13, limit=200)
        else:
            dt, _ = quad(lambda th: 1 / omega(th), 0.0, 2 * math.pi, epsabs=0, epsrel=1e-13, limit=200)
        v_end = r * omega(2 * math.pi)
        v_after = v_end * (r_next ** 2 + 2 * r * r) / (3 * r * r_next)
        if k in KEEP:
            rows.append((k, t, v_start, t + dt, v_end, v_after))
        t += dt
        v_start = v_after
    return rows


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "turns_reference.csv")
    with open(out, "w", newline="") as fh:
        fh.write("# Independent reference for the turn-by-turn model: energy integral per turn + quad for time.\n")
        fh.write(f"# alpha_deg=30 b_m={B} r0={R0} g={G0} density={RHO} length={L} v0=0; made by make_turns_reference.py\n")
        w = csv.writer(fh)
        w.writerow(["variant", "turn", "t_start_s", "v_start_m_s", "t_end_s", "v_end_m_s", "v_after_m_s"])
        for name, variant in (("turns", paper_turn), ("turns-exact", exact_turn)):
            for row in run(variant):
                w.writerow([name] + [row[0]] + [repr(x) for x in row[1:]])
    print("wrote", out)


if __name__ == "__main__":
    main()
