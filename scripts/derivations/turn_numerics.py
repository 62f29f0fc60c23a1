"""Turn-by-turn numerics for the contact forces, the hop and the collision variants
(docs/contact-forces.md §§4-6). Pure python (math only): each turn is evaluated
from its energy integral (theta'^2 as a function of theta, no time stepping),
so 2000 turns take well under a second; a fixed-step RK4 integration of the
equation of motion cross-checks the energy integral and the forces on the first
turns. Writes reference CSVs to scripts/derivations/reference/.

Run: python3 scripts/derivations/turn_numerics.py   (exits 1 on any FAIL)
"""

import math
import os

from _check import check, close, finish

PI = math.pi
TWO_PI = 2 * PI
HERE = os.path.dirname(os.path.abspath(__file__))
REF = os.path.join(HERE, "reference")

# defaults of the program (DESIGN.md)
B, R0, GRAV = 0.01, 0.1, 9.81


class Coeffs:
    """In-turn coefficients per unit m_k (re-derived in contact_forces.py):
    I/m_k = 3r^2/2 + c1 th - c2 sin th ; W/m_k = -G(r th + e1 th^2/2 - e2(1-cos)) + C(e3 th - e2 sin);
    M/m_k = 1 + mu th ; S_x/m_k = -e2 (1 - cos) ; S_y/m_k = r (1 + mu th) - e2 sin."""

    def __init__(self, r, b, exact):
        self.r, self.b = r, b
        if exact:
            d2 = b * (2 * r + b)
            d3 = b * (3 * r * r + 3 * r * b + b * b)
            d4 = b * (4 * r**3 + 6 * r * r * b + 4 * r * b * b + b**3)
            self.c1 = (r * r * d2 / 2 + d4 / 4) / (PI * r * r)
            self.c2 = 2 * d3 / (3 * PI * r)
            self.e1 = d2 / (2 * PI * r)
            self.e2 = d3 / (3 * PI * r * r)
            self.e3 = d2 * (2 * r + b) / (4 * PI * r * r)
            self.mu = d2 / (2 * PI * r * r)
        else:
            self.c1 = self.c2 = 2 * b * r / PI
            self.e1 = self.e2 = self.e3 = b / PI
            self.mu = b / (PI * r)


class Turn:
    """Turn k of nominal radius r, slope components G, C (m/s^2)."""

    def __init__(self, r, b, G, C, exact):
        self.k = Coeffs(r, b, exact)
        self.r, self.b, self.G, self.C = r, b, G, C

    def inertia(self, th):
        k = self.k
        return 1.5 * self.r**2 + k.c1 * th - k.c2 * math.sin(th), k.c1 - k.c2 * math.cos(th)

    def potential(self, th):
        k, G, C, r = self.k, self.G, self.C, self.r
        s, c = math.sin(th), math.cos(th)
        w = -G * (r * th + k.e1 * th * th / 2 - k.e2 * (1 - c)) + C * (k.e3 * th - k.e2 * s)
        dw = -G * (r + k.e1 * th - k.e2 * s) + C * (k.e3 - k.e2 * c)
        return w, dw

    def omega2(self, th, w0):
        i, _ = self.inertia(th)
        w, _ = self.potential(th)
        return (1.5 * self.r**2 * w0 * w0 - 2 * w) / i

    def thetadd(self, th, w2):
        i, di = self.inertia(th)
        _, dw = self.potential(th)
        return (-dw - 0.5 * di * w2) / i

    def forces(self, th, w2, wdd):
        """(N/m_k, F/m_k, M/m_k) from the momentum balance."""
        k, G, C, r = self.k, self.G, self.C, self.r
        s, c = math.sin(th), math.cos(th)
        m = 1 + k.mu * th
        n = m * C + k.e2 * (wdd * (1 - c) + w2 * s)
        f = m * G - wdd * (r * m - k.e2 * s) - w2 * (k.e1 - k.e2 * c)
        return n, f, m

    def along(self, th, w0):
        w2 = self.omega2(th, w0)
        wdd = self.thetadd(th, w2)
        return w2, wdd, self.forces(th, w2, wdd)


def golden_min(f, lo, hi, tol=1e-10):
    gr = (math.sqrt(5) - 1) / 2
    a, b = lo, hi
    c, d = b - gr * (b - a), a + gr * (b - a)
    fc, fd = f(c), f(d)
    while b - a > tol:
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - gr * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + gr * (b - a)
            fd = f(d)
    t = (a + b) / 2
    return t, f(t)


def minimise(f, lo, hi, n=64):
    """Global min of a smooth f on [lo, hi]: grid, then golden section around the best point."""
    h = (hi - lo) / n
    vals = [f(lo + i * h) for i in range(n + 1)]
    i = min(range(n + 1), key=lambda j: vals[j])
    a, b = max(lo, lo + (i - 1) * h), min(hi, lo + (i + 1) * h)
    t, v = golden_min(f, a, b)
    if vals[0] < v:
        t, v = lo, vals[0]
    if vals[n] < v:
        t, v = hi, vals[n]
    return t, v


def turn_extremes(turn, w0, th_end, g, want_f=True):
    """min N/(M g) and max |F|/N over [0, th_end] of a turn started at theta' = w0."""

    def n_over_mg(th):
        w2, wdd, (n, f, m) = turn.along(th, w0)
        return n / (m * g)

    def neg_ratio(th):
        w2, wdd, (n, f, m) = turn.along(th, w0)
        return -abs(f) / n if n > 0 else -1e300

    th_n, nmin = minimise(n_over_mg, 0.0, th_end)
    if not want_f:
        return nmin, th_n, math.nan, math.nan
    if nmin <= 0:  # N reaches 0: no friction ratio (the log hops)
        return nmin, th_n, math.inf, math.nan
    th_f, rneg = minimise(neg_ratio, 0.0, th_end)
    return nmin, th_n, -rneg, th_f


# ------------------------------------------------------------------ collisions


def pivot_geometry(r, b):
    """Corner of the new layer meets y = 0 at theta_c = 2 pi - delta, d ahead of C."""
    delta = math.acos(r / (r + b))
    d = math.sqrt(2 * r * b + b * b)
    return delta, d


def exact_body(r, b, th):
    """(M, S_x, S_y, I_C) per unit m_k of the exact disk + sector at theta."""
    k = Coeffs(r, b, True)
    m = 1 + k.mu * th
    sx = -k.e2 * (1 - math.cos(th))
    sy = r * m - k.e2 * math.sin(th)
    ic = 1.5 * r * r + k.c1 * th - k.c2 * math.sin(th)
    return m, sx, sy, ic, k


def pivot_collision(r, b, G, C, alpha, g, w_minus):
    """Impact at the corner E (L_E conserved, exact body at theta_c), pivot about E until the
    centre is above E, then the notch of the new layer is filled (L_E conserved) and its lift
    charged. Returns a dict; per unit m_k."""
    delta, d = pivot_geometry(r, b)
    thc = TWO_PI - delta
    m, sx, sy, ic, k = exact_body(r, b, thc)
    le_minus = ic - d * sx  # |L_E| / (m_k theta'-)
    ie = ic - 2 * d * sx + m * d * d
    w_plus = w_minus * le_minus / ie
    # impulse at E (per unit m_k): p- = w-(S_y, -S_x), p+ = w+(S_y, M d - S_x)
    jx = (w_plus - w_minus) * sy
    jy = w_plus * (m * d - sx) - w_minus * (-sx)
    # pivot: cm - E = rho_E (-sin psi, cos psi), psi decreasing by delta
    hx, hy = sx / m - d, sy / m
    rho_e = math.hypot(hx, hy)
    psi0 = math.atan2(-hx, hy)
    K = m * g * rho_e / ie  # phi'' = K sin(alpha - psi)

    def phid2(psi):
        return w_plus**2 + 2 * K * (math.cos(psi0 - alpha) - math.cos(psi - alpha))

    def n_e(psi):  # N_E/(M g)
        p2 = phid2(psi)
        pdd = K * math.sin(alpha - psi)
        return (C + rho_e * (pdd * math.sin(psi) - p2 * math.cos(psi))) / g

    def f_e(psi):
        p2 = phid2(psi)
        pdd = K * math.sin(alpha - psi)
        return (G - rho_e * (pdd * math.cos(psi) + p2 * math.sin(psi))) / g

    psi_end = psi0 - delta
    top = min(max(alpha, psi_end), psi0)
    stuck = phid2(top) <= 0
    out = dict(delta=delta, d=d, theta_c=thc, w_plus=w_plus, jx=jx, jy=jy, rho_e=rho_e, psi0=psi0,
               stuck=stuck, le_minus=le_minus, ie=ie, m=m)
    if stuck:
        return out
    psis = [psi0 - delta * i / 200 for i in range(201)]
    out["nmin_pivot"] = min(n_e(p) for p in psis)
    out["n_start"] = n_e(psi0)
    out["fratio_max_pivot"] = max(abs(f_e(p)) / n_e(p) for p in psis if n_e(p) > 0) if out["nmin_pivot"] > 0 else math.inf
    w_end = math.sqrt(phid2(psi_end))
    # fill the notch (annular sector of angle delta behind E): L_E conserved, lift charged
    R = r + b
    m_next = (R / r) ** 2
    ie_new = 1.5 * m_next * R * R
    w_fill = w_end * ie / ie_new
    dm = k.mu * delta
    dv_notch = C * (dm * (R + b / 2) - k.e2 * math.sin(delta)) - G * (dm * d / 2 - k.e2 * (1 - math.cos(delta)))
    t_new = 0.5 * ie_new * w_fill**2 - dv_notch
    out.update(w_end=w_end, dm=dm, dv_notch=dv_notch, m_next_check=m + dm - m_next)
    if t_new <= 0:
        out["stuck"] = True
        return out
    out["w_next"] = math.sqrt(2 * t_new / ie_new)
    out["kin_after_impact"] = 0.5 * ie * w_plus**2
    out["kin_before"] = 0.5 * ic * w_minus**2
    return out


def run(alpha_deg, turns, exact=False, collision="note", b=B, r0=R0, g=GRAV, v0=0.0, hop_stops=True, per_turn=None, want_f=True):
    """Runs the turn model; returns a summary dict. `per_turn(k, row)` receives each turn's row."""
    al = math.radians(alpha_deg)
    G, C = g * math.sin(al), g * math.cos(al)
    w0 = v0 / r0
    res = dict(hop=None, stuck=None, stall=None, pivot_hop=None, nmin=math.inf, fmax=0.0, turns=0)
    for k in range(turns):
        r = r0 + k * b
        turn = Turn(r, b, G, C, exact)
        if collision == "pivot":
            delta, _ = pivot_geometry(r, b)
            th_end = TWO_PI - delta
        else:
            th_end = TWO_PI
        # stall: theta'^2 must stay > 0
        _, w2min = minimise(lambda t: turn.omega2(t, w0), 1e-9, th_end, 32)
        if w2min <= 0:
            res["stall"] = k
            break
        nmin, th_n, fmax, th_f = turn_extremes(turn, w0, th_end, g, want_f)
        w_end = math.sqrt(turn.omega2(th_end, w0))
        row = dict(k=k, v_beg=r * w0, nmin=nmin, th_n=th_n, fmax=fmax, th_f=th_f, v_end=r * w_end)
        res["nmin"] = min(res["nmin"], nmin)
        if nmin < 0:
            res["hop"] = (k, th_n)
            if hop_stops:
                if per_turn:
                    per_turn(k, row)
                break
        else:
            res["fmax"] = max(res["fmax"], fmax)
        R = r + b
        if collision == "pivot":
            pc = pivot_collision(r, b, G, C, al, g, w_end)
            row["pivot"] = pc
            if pc["stuck"]:
                res["stuck"] = k
                if per_turn:
                    per_turn(k, row)
                break
            if pc["nmin_pivot"] < 0 and res["pivot_hop"] is None:
                res["pivot_hop"] = k
                if hop_stops:
                    if per_turn:
                        per_turn(k, row)
                    break
            w0 = pc["w_next"]
        else:
            v_note = r * w_end * (R * R + 2 * r * r) / (3 * r * R)
            v2 = v_note**2 - (4.0 / 3.0 * C * b if collision == "charged" else 0.0)
            if v2 <= 0:
                res["stuck"] = k
                break
            w0 = math.sqrt(v2) / R
        row["v_after"] = R * w0
        res["turns"] = k + 1
        res["last"] = row
        if per_turn:
            per_turn(k, row)
    res["w0_last"] = w0
    return res


def hop_turn(alpha_deg, turns, **kw):
    r = run(alpha_deg, turns, want_f=False, **kw)
    return r["hop"]


def critical_angle(turns, lo, hi, **kw):
    """Smallest slope (deg) at which the log hops within `turns` turns (bisection on [lo, hi])."""
    assert hop_turn(lo, turns, **kw) is None and hop_turn(hi, turns, **kw) is not None
    for _ in range(24):
        mid = (lo + hi) / 2
        if hop_turn(mid, turns, **kw) is None:
            lo = mid
        else:
            hi = mid
    return hi


def main():
    os.makedirs(REF, exist_ok=True)
    print("== hop within a turn (note collision, defaults b=0.01, r0=0.1)")
    r30 = run(30.0, 2000)
    check("30 deg, turns: no hop in 2000 turns", r30["hop"] is None and r30["turns"] == 2000)
    close("30 deg: min N/(M g) over 2000 turns -> cos a - sin a/2 = 0.61603 (to 1e-3)", r30["last"]["nmin"],
          math.cos(math.radians(30)) - 0.5 * math.sin(math.radians(30)), rel=1e-3)
    print(f"     30 deg: min N/(Mg) over the run {r30['nmin']:.6f}; last turn {r30['last']['nmin']:.6f}")
    r30e = run(30.0, 2000, exact=True)
    check("30 deg, turns-exact: no hop in 2000 turns", r30e["hop"] is None and r30e["turns"] == 2000)
    r80 = run(80.0, 2000)
    check("80 deg, turns: hops", r80["hop"] is not None)
    r80e = run(80.0, 2000, exact=True)
    check("80 deg, turns-exact: hops", r80e["hop"] is not None)
    print(f"     80 deg: hop in turn {r80['hop'][0]} at theta = {r80['hop'][1]:.4f} rad (turns); "
          f"{r80e['hop'][0]} at {r80e['hop'][1]:.4f} (turns-exact)")
    # critical angle for K turns vs closed form tan a_K = (1 + e c_C)/(1/2 - e c_G), e = b/r_{K-1}
    c_c = 1.5 + 8 / (13 * PI)
    c_g = 1 / PI + 14 / 39 - 1
    rows = []
    for K in (20, 100, 500, 2000):
        e = B / (R0 + (K - 1) * B)
        a_cf = math.degrees(math.atan((1 + e * c_c) / (0.5 - e * c_g)))
        a_num = critical_angle(K, a_cf - 0.1, a_cf + 0.1)
        a_num_ex = critical_angle(K, a_cf - 0.5, a_cf + 0.1, exact=True)
        rows.append((K, a_num, a_num_ex, a_cf))
        print(f"     K={K:5d}: hop within K turns above {a_num:.6f} deg (turns), {a_num_ex:.6f} (turns-exact); "
              f"O(b/r) closed form {a_cf:.6f}; K->inf 63.434949")
    for K, a_num, a_ex, a_cf in rows:
        if K >= 200:
            close(f"critical angle within {K} turns: numeric vs O(b/r) closed form (1e-4 rel)", a_num, a_cf, rel=1e-4)
    close("critical angle within 2000 turns -> atan 2 (2e-4 rel)", rows[-1][1], math.degrees(math.atan(2)), rel=2e-4)
    with open(os.path.join(REF, "hop_angles.csv"), "w") as fh:
        fh.write("# made by scripts/derivations/turn_numerics.py; defaults b=0.01 m, r0=0.1 m, g=9.81, v0=0, collision note\n")
        fh.write("# alpha_crit_deg: smallest slope at which N reaches 0 within the first K turns (bisection, to 4e-8 deg)\n")
        fh.write("# closed_form_deg: atan((1 + e c_C)/(1/2 - e c_G)), e = b/r_{K-1}, c_C = 3/2 + 8/(13 pi), c_G = 1/pi + 14/39 - 1\n")
        fh.write("turns,alpha_crit_turns_deg,alpha_crit_turns_exact_deg,closed_form_deg\n")
        for K, a_num, a_ex, a_cf in rows:
            fh.write(f"{K},{a_num:.9f},{a_ex:.9f},{a_cf:.9f}\n")

    print("== min N/(M g) per turn for several slopes (figure data)")
    with open(os.path.join(REF, "min_normal_per_turn.csv"), "w") as fh:
        fh.write("# made by scripts/derivations/turn_numerics.py; model turns (paper) and turns-exact, collision note, defaults\n")
        fh.write("# per turn k: min over the turn of N/(M g) (M = mass in the model's bookkeeping), theta there, max |F|/N\n")
        fh.write("variant,alpha_deg,turn,v_start_m_s,min_n_over_mg,theta_at_min_rad,max_f_over_n,theta_at_max_rad\n")
        for exact in (False, True):
            for al in (10, 30, 45, 60, 63, 64, 70, 80):
                picks = {0, 1, 2, 3, 4, 9, 19, 49, 99, 199, 499, 999, 1999}

                def rec(k, row, al=al, exact=exact):
                    if k in picks or row["nmin"] < 0:
                        fh.write(f"{'turns-exact' if exact else 'turns'},{al},{k},{row['v_beg']:.12g},{row['nmin']:.12g},"
                                 f"{row['th_n']:.10g},{row['fmax']:.12g},{row['th_f']:.10g}\n")

                run(al, 2000, exact=exact, per_turn=rec)
    # late-turn asymptotes and the smallest mu that keeps the log rolling over 2000 turns
    mu_rows = []
    for al in (10, 30, 45, 60):
        rr = run(al, 2000)
        best = {}

        def rec_mu(k, row, best=best):
            if not best or row["fmax"] > best["fmax"]:
                best.update(row)

        rr_ex = run(al, 2000, exact=True, per_turn=rec_mu)
        mu_rows.append((al, rr["fmax"], rr_ex["fmax"], best["k"], best["th_f"]))
        a = math.radians(al)
        close(f"{al} deg: last-turn min N/(M g) -> cos a - sin a/2 (abs 1e-3)", rr["last"]["nmin"], math.cos(a) - math.sin(a) / 2, rel=0, abs_=1e-3)
        t = math.tan(a)
        close(f"{al} deg: last-turn max |F|/N -> 4 tan/(3(4 - tan^2)) (3e-3)", rr["last"]["fmax"], 4 * t / (3 * (4 - t * t)), rel=3e-3)
        print(f"     {al} deg: mu_min over 2000 turns {rr['fmax']:.6f} (turns), late-turn closed form {4*t/(3*(4-t*t)):.6f}, "
              f"snowless tan/3 {t/3:.6f}")

    with open(os.path.join(REF, "turn_mu_min.csv"), "w") as fh:
        fh.write("# made by scripts/derivations/turn_numerics.py; defaults, collision note, from rest, 2000 turns\n")
        fh.write("# mu_min = max over the run of |F|/N; late_turn_closed_form = 4 tan(a)/(3 (4 - tan(a)^2)); snowless = tan(a)/3\n")
        fh.write("alpha_deg,mu_min_turns,mu_min_turns_exact,turn_of_max_exact,theta_of_max_exact_rad,late_turn_closed_form,snowless\n")
        for al, m1, m2, kk, thf in mu_rows:
            t = math.tan(math.radians(al))
            fh.write(f"{al},{m1:.10g},{m2:.10g},{kk},{thf:.8g},{4*t/(3*(4-t*t)):.10g},{t/3:.10g}\n")

    print("== long-run v^2/(pi G b k^2/2) at turn start, by collision variant (pivot with the hop ignored)")
    for coll in ("note", "charged", "pivot"):
        rr = run(30.0, 2000, collision=coll, hop_stops=False)
        k = rr["turns"]
        G = GRAV * 0.5
        ratio = (rr["last"]["v_after"]) ** 2 / (PI * G * B * k * k / 2)
        C = GRAV * math.cos(math.radians(30.0))
        c_b = {"note": 24, "charged": 36, "pivot": 36}[coll]
        want = 1 + (2 * R0 / B - (28 + 2 * c_b * C / (PI * G)) / 39) / k  # 1 + B/(A k), B from contact_forces.py
        print(f"     {coll:8s}: K={k}, v_start(K)^2/(pi G b K^2/2) = {ratio:.7f}; 1 + B/(A K) = {want:.7f}")
        # the next term is O(K^-2) relative, ~ 2 (r0/b)^2/K^2 = 5e-5 here; pivot uses charged's B (it equals
        # charged to O(K) in v^2; its own O(K^(1/2)) terms are below this tolerance at K = 2000)
        close(f"{coll}: v_start(K)^2 = A K^2 + B K to 5e-5 at K = 2000", ratio, want, rel=5e-5)

    print("== collisions: pivot hop at the first step, stuck")
    for al in (5, 6, 7, 8, 10, 30):
        rr = run(al, 5, collision="pivot")
        print(f"     pivot {al:3d} deg: hop at the edge in turn {rr['pivot_hop']}, in-turn hop {rr['hop']}, stuck {rr['stuck']}, stall {rr['stall']}")
    rr = run(30.0, 5, collision="pivot")
    check("pivot, 30 deg: the log leaves the edge at the first step (turn 0)", rr["pivot_hop"] == 0)

    def first_step_hops(al):
        return run(al, 1, collision="pivot")["pivot_hop"] == 0

    lo, hi = 1.0, 30.0
    for _ in range(50):
        mid = (lo + hi) / 2
        if first_step_hops(mid):
            hi = mid
        else:
            lo = mid
    print(f"     pivot: the log leaves the edge at the first step for alpha > {hi:.6f} deg (defaults, from rest)")
    lead = math.degrees(math.atan(3 / (8 * PI)))
    print(f"     leading order (8 pi/3) tan a > 1: {lead:.4f} deg")
    pv = run(30.0, 1, collision="pivot", hop_stops=False)
    # L_E conservation at the impact: recompute both sides
    with open(os.path.join(REF, "pivot_first_step.csv"), "w") as fh:
        fh.write("# made by scripts/derivations/turn_numerics.py; first collision (turn 0) with --collision pivot, defaults, from rest\n")
        fh.write("# per unit m_0 = pi rho l r0^2; w = rotation rate (rad/s); impact with the exact disk+sector at theta_c\n")
        fh.write("variant,alpha_deg,theta_c_rad,d_m,w_minus,w_plus,impulse_x_m_s,impulse_y_m_s,n_over_mg_after_impact,min_n_over_mg_pivot,w_end_pivot,w_next\n")
        for exact in (False, True):
            for al in (5.0, 10.0, 30.0):
                out = {}

                def rec(k, row, out=out):
                    out.update(row)

                run(al, 1, exact=exact, collision="pivot", hop_stops=False, per_turn=rec)
                p = out["pivot"]
                w_minus = out["v_end"] / R0
                fh.write(f"{'turns-exact' if exact else 'turns'},{al},{p['theta_c']:.12g},{p['d']:.12g},{w_minus:.12g},{p['w_plus']:.12g},"
                         f"{p['jx']:.12g},{p['jy']:.12g},{p['n_start']:.12g},{p['nmin_pivot']:.12g},{p['w_end']:.12g},{p['w_next']:.12g}\n")
    # stuck: a shallow slope with an initial speed just enough to reach the step (window 0.4 <= v0 <= 0.5 m/s)
    for coll in ("pivot", "charged"):
        for exact in (False, True):
            rr = run(1.0, 3, exact=exact, collision=coll, v0=0.45, want_f=False)
            check(f"{coll} ({'turns-exact' if exact else 'turns'}), 1 deg, v0 = 0.45 m/s: stuck at the first step",
                  rr["stuck"] == 0 and rr["stall"] is None and rr["pivot_hop"] is None)
    rr = run(1.0, 3, collision="note", v0=0.45, want_f=False)
    check("note, 1 deg, v0 = 0.45 m/s: no stuck (the jump is free), completes turn 0", rr["stuck"] is None and rr["turns"] >= 1)

    rk4_crosscheck()
    finish()


def rk4_crosscheck():
    """Integrates theta'' = (-W' - I' theta'^2/2)/I with RK4 over the first two turns at 30 deg and
    checks (i) theta'(theta) against the energy integral, (ii) N and F from the closed forms against
    the momentum p = m_k theta' (S_y, -S_x) differentiated by central differences along the
    trajectory (the recipe of docs/contact-forces.md §7)."""
    print("== RK4 cross-check of the energy integral and of N, F by finite differences of p(t)")
    al = math.radians(30.0)
    G, C = GRAV * math.sin(al), GRAV * math.cos(al)
    for exact in (False, True):
        turn = Turn(R0, B, G, C, exact)
        k = turn.k

        def f(y):
            th, w = y
            return (w, turn.thetadd(th, w * w))

        h = 1e-4
        y = (0.0, 0.0)
        traj = [(0.0, y)]
        t = 0.0
        while y[0] < 6.0:
            k1 = f(y)
            k2 = f((y[0] + h / 2 * k1[0], y[1] + h / 2 * k1[1]))
            k3 = f((y[0] + h / 2 * k2[0], y[1] + h / 2 * k2[1]))
            k4 = f((y[0] + h * k3[0], y[1] + h * k3[1]))
            y = (y[0] + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]), y[1] + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))
            t += h
            traj.append((t, y))
        err_w = max(abs(w - math.sqrt(max(turn.omega2(th, 0.0), 0.0))) for _, (th, w) in traj[10:])
        check(f"RK4 vs energy integral ({'exact' if exact else 'paper'}): max |theta' - sqrt(omega2(theta))| < 1e-9", err_w < 1e-9, f"{err_w}")

        def p(th, w):  # per unit m_k
            m = 1 + k.mu * th
            return (w * (R0 * m - k.e2 * math.sin(th)), w * k.e2 * (1 - math.cos(th)))

        worst = 0.0
        for i in range(200, len(traj) - 1, 997):
            (t0, y0), (t1, y1), (t2, y2) = traj[i - 1], traj[i], traj[i + 1]
            pa, pc = p(*y0), p(*y2)
            dpx, dpy = (pc[0] - pa[0]) / (t2 - t0), (pc[1] - pa[1]) / (t2 - t0)
            th, w = y1
            m = 1 + k.mu * th
            n_fd, f_fd = dpy + m * C, m * G - dpx
            n_cf, f_cf, _ = turn.forces(th, w * w, turn.thetadd(th, w * w))
            worst = max(worst, abs(n_fd - n_cf) / GRAV, abs(f_fd - f_cf) / GRAV)
        check(f"N, F closed form vs finite differences of p ({'exact' if exact else 'paper'}): < 1e-6 g", worst < 1e-6, f"{worst}")


if __name__ == "__main__":
    main()
