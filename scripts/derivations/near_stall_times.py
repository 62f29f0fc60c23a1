"""Reference times of turns that nearly stall (issue 32, item 1; docs/turn-model.md,
"The closed-form path", (T3)): t = integral over [0, 2 pi] of sqrt(I/E) d theta, where
E = I(0) theta'_0^2 - 2 W(theta) dips close to 0 inside the turn, so that the integrand has a
tall, narrow (logarithmic) peak at the minimum of E.

The turn is the model as the program holds it: the slope components G, C, the radius r, the
in-turn coefficients c1, c2, e1, e2, e3 and I(0) theta'_0^2 are the doubles the program
computes (the same operations in IEEE double here, printed in the CSV so that the Rust test can
check it uses the very same numbers). Everything after that is exact arithmetic at 50 digits
(mpmath): the minimum of E by Newton's method on W' = 0, and the time by tanh-sinh quadrature
split at that minimum (mpmath's quad, with its error estimate, which must be below 1e-25 of
the time). Why the doubles matter: near a stall the time is ill-conditioned, t ~ c ln(1/E_min),
and E_min is a difference of terms 1e10 times larger at 1e-10 degrees above the stall slope, so
a rounding of G at 1e-16 moves t by ~1e-7 relative; the program's time is compared with the
exact time of its own numbers.

Cases, for both turn models (`turns`, eq. (73); `turns-exact`, the disk and annular sector):
  rest:  turn 0 from rest on alpha = alpha* + delta degrees (alpha*: the turn-0 stall slope,
         the largest Q/P, docs/turn-model.md "Stall in the first turn"), b = 0.01 m, r0 = 0.1 m;
  speed: turn 0 on alpha = 1 degree from v0 = v* (1 + delta), v* the least start speed that
         clears the turn (E_min = 0);
  later: turn 3 (r = r0 + 3 b) on alpha = 1 degree from theta'_0 = w* (1 + delta) likewise;
  stall: turn 0 from rest on alpha = alpha* - delta: the log stalls where E first reaches 0, at
         theta_s (in the column theta_min_rad, e_min 0), and the time is the time to theta_s;
delta = 1e-3 ... 1e-10.

And the angle reached at t_end = 3, 8, 12, 16 s in turn 0 of `turns` from rest 1e-8 and 1e-10 degrees
above the stall slope (before, close before, close after and past the minimum of E;
reference/near_stall_angles.csv).

Run: python3 scripts/derivations/near_stall_times.py   (writes reference/near_stall_times.csv and
reference/near_stall_angles.csv; exits 1 on any FAIL; ~2 min)
"""

import math
import os

import mpmath as mp

from _check import check, finish

mp.mp.dps = 50
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "reference", "near_stall_times.csv")
OUT_ANGLES = os.path.join(HERE, "reference", "near_stall_angles.csv")

B, R0, GRAV = 0.01, 0.1, 9.81
DELTAS = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]


def coefficients(r, b, exact):
    """(c1, c2, e1, e2, e3) as the program computes them, in IEEE double
    (InTurnCoefficients::paper, exact_turn_coefficients with RingMoments)."""
    pi = math.pi
    if not exact:
        c = 2.0 * b * r / pi
        e = b / pi
        return (c, c, e, e, e)
    d2 = b * (2.0 * r + b)
    d3 = b * (3.0 * r * r + 3.0 * r * b + b * b)
    d4 = b * (4.0 * r * r * r + 6.0 * r * r * b + 4.0 * r * b * b + b * b * b)
    r2 = r * r
    return (
        (r2 * d2 / 2.0 + d4 / 4.0) / (pi * r2),
        2.0 * d3 / (3.0 * pi * r),
        d2 / (2.0 * pi * r),
        d3 / (3.0 * pi * r2),
        d2 * (2.0 * r + b) / (4.0 * pi * r2),
    )


class Turn:
    """One turn, exact arithmetic on the double inputs."""

    def __init__(self, r, b, exact, g_along, g_normal):
        self.r, self.b = r, b
        self.k = coefficients(r, b, exact)
        self.G, self.C = mp.mpf(g_along), mp.mpf(g_normal)
        self.i0 = mp.mpf(1.5 * r * r)

    def inertia(self, t):
        c1, c2 = (mp.mpf(x) for x in self.k[:2])
        return self.i0 + c1 * t - c2 * mp.sin(t)

    def p_q(self, t):
        """W = -G P + C Q."""
        _, _, e1, e2, e3 = (mp.mpf(x) for x in self.k)
        r = mp.mpf(self.r)
        return r * t + e1 * t * t / 2 - e2 * (1 - mp.cos(t)), e3 * t - e2 * mp.sin(t)

    def w(self, t):
        p, q = self.p_q(t)
        return -self.G * p + self.C * q

    def dw(self, t):
        _, _, e1, e2, e3 = (mp.mpf(x) for x in self.k)
        r = mp.mpf(self.r)
        return -self.G * (r + e1 * t - e2 * mp.sin(t)) + self.C * (e3 - e2 * mp.cos(t))

    def d2w(self, t):
        _, _, e1, e2, _ = (mp.mpf(x) for x in self.k)
        return -self.G * (e1 - e2 * mp.cos(t)) + self.C * e2 * mp.sin(t)

    def w_max(self):
        """The largest W on (0, 2 pi): a grid, then Newton on W' = 0."""
        grid = [2 * mp.pi * i / 400 for i in range(1, 401)]
        best = max(grid, key=self.w)
        t = mp.findroot(self.dw, best)
        check("W has an interior maximum", 0 < t < 2 * mp.pi and self.d2w(t) < 0, f"theta {t}")
        return t, self.w(t)


def stall_slope_deg(exact):
    """alpha* in degrees: tan alpha* = max over theta of Q/P (turn 0 from rest, unit G and C)."""
    turn = Turn(R0, B, exact, 1.0, 0.0)
    ratio = lambda t: turn.p_q(t)[1] / turn.p_q(t)[0]
    grid = [2 * mp.pi * i / 400 for i in range(1, 401)]
    t = mp.findroot(lambda x: mp.diff(ratio, x), max(grid, key=ratio))
    return mp.degrees(mp.atan(ratio(t)))


def duration(turn, e0):
    """t over [0, 2 pi] by tanh-sinh split at the minimum of E = e0 - 2W, with its error."""
    t_min, w_max = turn.w_max()
    e_min = e0 - 2 * w_max
    check("E stays positive", e_min > 0, f"E_min {e_min}")
    f = lambda t: mp.sqrt(turn.inertia(t) / (e0 - 2 * turn.w(t)))
    value, err = mp.quad(f, [0, t_min, 2 * mp.pi], error=True, maxdegree=10)
    check("quadrature error estimate", err < 1e-25 * value, f"{err} of {value}")
    return t_min, e_min, value, err


def time_to_stall(turn):
    """From rest to the first zero theta_s of E = -2W (before the maximum of W): bisection at
    50 digits, then tanh-sinh over [0, theta_s] (E ~ theta at 0, ~ theta_s - theta at the end)."""
    t_max, w_max = turn.w_max()
    check("E reaches 0 in the turn", w_max > 0, f"W_max {w_max}")
    energy = lambda t: -2 * turn.w(t)
    lo, hi = mp.mpf("0.5"), t_max
    check("E > 0 at 0.5 rad", energy(lo) > 0)
    for _ in range(200):
        mid = (lo + hi) / 2
        if energy(mid) > 0:
            lo = mid
        else:
            hi = mid
    f = lambda t: mp.sqrt(turn.inertia(t) / energy(t))
    value, err = mp.quad(f, [0, lo], error=True, maxdegree=10)
    check("quadrature error estimate (stall)", err < 1e-25 * value, f"{err} of {value}")
    return lo, value, err


def angle_at_time(turn, t_end):
    """The angle reached at t_end from rest: bisection on t(theta) - t_end to 1e-12 rad, then
    Newton's method (d t/d theta = sqrt(I/E)); the quadrature split at the minimum of E."""
    t_min, _ = turn.w_max()
    f = lambda t: mp.sqrt(turn.inertia(t) / (-2 * turn.w(t)))
    t_of = lambda th: mp.quad(f, [0, th] if th <= t_min else [0, t_min, th])
    lo, hi = mp.mpf(0), 2 * mp.pi
    while hi - lo > mp.mpf("1e-12"):
        mid = (lo + hi) / 2
        if t_of(mid) < t_end:
            lo = mid
        else:
            hi = mid
    th = (lo + hi) / 2
    for _ in range(6):
        th = th - (t_of(th) - t_end) / f(th)
    check("angle at time", abs(t_of(th) - t_end) < mp.mpf("1e-30"), f"{th}")
    return th


def main():
    rows = []
    for exact, name in [(False, "turns"), (True, "turns-exact")]:
        alpha_star = stall_slope_deg(exact)
        for delta in DELTAS:
            # rest: alpha = alpha* + delta (a double), from rest
            alpha_deg = float(alpha_star + delta)
            alpha = alpha_deg * (math.pi / 180.0)
            g_along, g_normal = GRAV * math.sin(alpha), GRAV * math.cos(alpha)
            turn = Turn(R0, B, exact, g_along, g_normal)
            t_min, e_min, t, err = duration(turn, mp.mpf(0))
            rows.append((name, "rest", 0, delta, alpha_deg, 0.0, 0.0, R0, g_along, g_normal,
                         turn.k, t_min, e_min, t, err))
            # stall: alpha = alpha* - delta, from rest: the time to the first zero of E
            alpha_deg = float(alpha_star - delta)
            alpha = alpha_deg * (math.pi / 180.0)
            g_along, g_normal = GRAV * math.sin(alpha), GRAV * math.cos(alpha)
            turn = Turn(R0, B, exact, g_along, g_normal)
            theta_s, t, err = time_to_stall(turn)
            rows.append((name, "stall", 0, delta, alpha_deg, 0.0, 0.0, R0, g_along, g_normal,
                         turn.k, theta_s, mp.mpf(0), t, err))
            # speed (turn 0) and later (turn 3) on 1 degree
            alpha_deg = 1.0
            alpha = alpha_deg * (math.pi / 180.0)
            g_along, g_normal = GRAV * math.sin(alpha), GRAV * math.cos(alpha)
            for case, k in [("speed", 0), ("later", 3)]:
                r = R0 + k * B
                turn = Turn(r, B, exact, g_along, g_normal)
                _, w_max = turn.w_max()
                w_star = mp.sqrt(2 * w_max / turn.i0)
                if case == "speed":
                    v0 = float(r * w_star * (1 + delta))
                    omega0 = v0 / r
                else:
                    v0 = 0.0
                    omega0 = float(w_star * (1 + delta))
                e0 = 1.5 * r * r * omega0 * omega0
                t_min, e_min, t, err = duration(turn, mp.mpf(e0))
                rows.append((name, case, k, delta, alpha_deg, v0, omega0, r, g_along, g_normal,
                             turn.k, t_min, e_min, t, err))
        print(f"{name}: stall slope {mp.nstr(alpha_star, 16)} deg")
    with open(OUT, "w") as out:
        out.write("# made by scripts/derivations/near_stall_times.py: times of nearly stalling turns, "
                  "b=0.01 m, r0=0.1 m, g=9.81, exact arithmetic (50 digits) on the program's doubles\n")
        out.write("# cases: rest (turn 0 from rest, alpha = alpha* + delta deg), speed (turn 0, alpha 1 deg, "
                  "v0 = v*(1 + delta)), later (turn 3, alpha 1 deg, omega0 = w*(1 + delta)), stall (turn 0 from rest, "
                  "alpha = alpha* - delta: theta_min_rad is the stall angle, time_s the time to it)\n")
        out.write("model,case,turn,delta,alpha_deg,v0_m_s,omega0_rad_s,r_m,g_along,g_normal,"
                  "c1,c2,e1,e2,e3,theta_min_rad,e_min,time_s,error_estimate_s\n")
        for (name, case, k, delta, alpha_deg, v0, omega0, r, ga, gn, coef, t_min, e_min, t, err) in rows:
            doubles = [alpha_deg, v0, omega0, r, ga, gn, *coef]
            out.write(",".join([name, case, str(k), repr(delta)] + [repr(x) for x in doubles]
                               + [mp.nstr(t_min, 20), mp.nstr(e_min, 20), mp.nstr(t, 25),
                                  mp.nstr(err, 3)]) + "\n")
    print(f"wrote {OUT}: {len(rows)} rows")
    # The angle reached at a given time inside a nearly stalling turn (`turns` from rest,
    # 1e-8 and 1e-10 degrees above the stall slope): before, near and after the minimum of E.
    alpha_star = stall_slope_deg(False)
    with open(OUT_ANGLES, "w") as out:
        out.write("# made by scripts/derivations/near_stall_times.py: the angle reached at t_end in turn 0 "
                  "of turns from rest, alpha = alpha* + delta deg, b=0.01 m, r0=0.1 m, g=9.81, 50 digits\n")
        out.write("delta,alpha_deg,t_end_s,theta_rad\n")
        for delta in [1e-8, 1e-10]:
            alpha_deg = float(alpha_star + delta)
            alpha = alpha_deg * (math.pi / 180.0)
            turn = Turn(R0, B, False, GRAV * math.sin(alpha), GRAV * math.cos(alpha))
            for t_end in [3.0, 8.0, 12.0, 16.0]:
                th = angle_at_time(turn, t_end)
                out.write(f"{delta!r},{alpha_deg!r},{t_end!r},{mp.nstr(th, 20)}\n")
    print(f"wrote {OUT_ANGLES}")
    finish()


if __name__ == "__main__":
    main()
