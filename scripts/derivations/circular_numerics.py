"""Circular models of §2 for the log and the ball: contact forces along a default run,
the smallest mu that keeps each rolling, and reference values of a, N, F at given states
(docs/contact-forces.md §§1, 6; docs/snowball-and-losses.md §1). Pure python (math only),
generic formulas of sphere.py (which checks them against the note symbolically).

Run: python3 scripts/derivations/circular_numerics.py   (exits 1 on any FAIL)
"""

import math
import os

from _check import check, close, finish

PI = math.pi
HERE = os.path.dirname(os.path.abspath(__file__))
REF = os.path.join(HERE, "reference")

MODELS = ("torque-cm", "torque-contact", "energy", "energy-thin", "lagrangian-printed", "quasi-circular", "quasi-circular-lift")
ALIAS = {"torque-cm": "eq4", "torque-contact": "eq6", "energy": "eq14", "energy-thin": "eq15",
         "lagrangian-printed": "eq21", "quasi-circular": "eq32", "quasi-circular-lift": "eq32+36"}


class Body:
    """Cylinder (I = M r^2/2, M = pi rho l r^2) or sphere (I = 2 M r^2/5, M = 4/3 pi rho r^3,
    swath w = 2r); both have pi r^2 = pi r0^2 + b x."""

    def __init__(self, shape, b, r0, rho=400.0, length=1.0):
        self.shape, self.b, self.r0, self.rho, self.length = shape, b, r0, rho, length
        self.k = 0.5 if shape == "cylinder" else 0.4
        self.eps = 1.0 if shape == "cylinder" else 1.5  # lam = eps b/(pi r^2)

    def geom(self, x):
        b = self.b
        r = math.sqrt(self.r0**2 + b * x / PI)
        lam = self.eps * b / (PI * r * r)
        rp = b / (2 * PI * r)
        rpp = -b * b / (4 * PI**2 * r**3)
        return r, lam, rp, rpp

    def mass(self, r):
        return PI * self.rho * self.length * r * r if self.shape == "cylinder" else 4 / 3 * PI * self.rho * r**3

    def area(self, r):
        return 2 * r * self.length if self.shape == "cylinder" else PI * r * r


def accel(model, body, x, v, G, C, loss=None):
    """a(x, v) of the model, with optional losses (drag C_d, air density, c_rr, e_c)."""
    r, lam, rp, rpp = body.geom(x)
    k, b = body.k, body.b
    u = v * v
    if model == "torque-cm":
        ieff, rhs = 1 + k, G - (1 + k) * lam * u - k * rp / r * u
    elif model == "torque-contact":
        ieff, rhs = 1 + k, G - (1 + k) * (lam + rp / r) * u
    elif model == "energy":
        ieff, rhs = 1 + k + rp * rp, G - (0.5 * lam * (1 + k + rp * rp) + rp * rpp) * u - C * (lam * (r + b / 2) + rp)
    elif model == "energy-thin":
        ieff, rhs = 1 + k, G - 0.5 * lam * (1 + k) * u - C * (lam * r + rp)
    elif model == "lagrangian-printed":
        ieff, rhs = 1 + k + rp * rp, G - (lam * (1 + k + rp * rp) + 2 * rp * rpp) * u - C * (lam * (r + b / 2) + rp)
    elif model == "quasi-circular":
        ieff, rhs = 1 + k, G - 0.5 * (1 + k) * lam * u
    elif model == "quasi-circular-lift":
        ieff, rhs = 1 + k, G - 0.5 * (1 + k) * lam * u - C * (lam * r + rp)
    elif model == "snowless":
        ieff, rhs = 1 + k, G
    else:
        raise ValueError(model)
    if loss:
        cd, rho_a, crr, ec = loss
        m = body.mass(r)
        fd = 0.5 * rho_a * cd * body.area(r) * u / m
        fc = ec * lam if model != "snowless" else 0.0
        rhs -= fd + fc + crr * (C + (lam * rp + rpp) * u if model != "snowless" else C)
        ieff += crr * rp if model != "snowless" else 0.0
    return rhs / ieff


def forces(model, body, x, v, a, G, C):
    """(N/M, F/M) from the momentum balance, p = M (v, r' v)."""
    if model == "snowless":
        return C, G - a
    r, lam, rp, rpp = body.geom(x)
    u = v * v
    return C + (lam * rp + rpp) * u + rp * a, G - a - lam * u


def run(model, body, alpha_deg, t_end=100.0, dt=1e-3, g=9.81):
    al = math.radians(alpha_deg)
    G, C = g * math.sin(al), g * math.cos(al)
    x, v, t = 0.0, 0.0, 0.0
    f = lambda x_, v_: (v_, accel(model, body, x_, v_, G, C))  # noqa: E731
    worst, at, nmin = 0.0, 0.0, math.inf
    while t < t_end - 1e-12:
        a = accel(model, body, x, v, G, C)
        n, fr = forces(model, body, x, v, a, G, C)
        nmin = min(nmin, n / g)
        if abs(fr) / n > worst:
            worst, at = abs(fr) / n, t
        k1 = f(x, v)
        k2 = f(x + dt / 2 * k1[0], v + dt / 2 * k1[1])
        k3 = f(x + dt / 2 * k2[0], v + dt / 2 * k2[1])
        k4 = f(x + dt * k3[0], v + dt * k3[1])
        x += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        v += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        t += dt
    a = accel(model, body, x, v, G, C)
    n, fr = forces(model, body, x, v, a, G, C)
    if abs(fr) / n > worst:
        worst, at = abs(fr) / n, t
    return dict(x=x, v=v, a=a, mu=worst, t_mu=at, nmin=nmin, G=G, C=C)


def main():
    os.makedirs(REF, exist_ok=True)
    al = 30.0
    tn = math.tan(math.radians(al))
    b, r0 = 0.01, 0.1
    rows = []
    print("== default run (30 deg, b 0.01, r0 0.1, 100 s, RK4 dt 1e-3): smallest mu, min N/(M g)")
    for shape in ("cylinder", "sphere"):
        body = Body(shape, b, r0)
        for model in ("snowless",) + MODELS:
            res = run(model, body, al)
            rows.append((shape, model, res))
            print(f"     {shape:8s} {model:20s} mu_min {res['mu']:.6f} at t = {res['t_mu']:.3f} s; min N/(Mg) {res['nmin']:.6f}; "
                  f"a(100 s)/G {res['a'] / res['G']:.5f}")
            check(f"{shape} {model}: N > 0 throughout (no hop)", res["nmin"] > 0)
    res = {(s, m): r for s, m, r in rows}
    close("cylinder snowless: mu_min = tan/3 exactly", res[("cylinder", "snowless")]["mu"], tn / 3, rel=1e-12)
    close("sphere snowless: mu_min = (2/7) tan", res[("sphere", "snowless")]["mu"], 2 * tn / 7, rel=1e-12)
    # drag-only log models from rest: closed form in s = pi r^2 (contact_forces.py)
    for model, c in (("torque-cm", 7 / 6), ("torque-contact", 1.5), ("quasi-circular", 0.5)):
        r_ = res[("cylinder", model)]
        G, C = r_["G"], r_["C"]
        s0 = PI * r0 * r0
        s_end = s0 + b * r_["x"]
        qq = 4 * G / (3 * (1 + 2 * c)) * (1 - (s0 / s_end) ** (1 + 2 * c))
        rr = math.sqrt(s_end / PI)
        if c >= 1:
            F = G / 3 + (c - 1) * qq
            N = C + b / (2 * PI * rr) * (2 * G / 3 + (0.5 - c) * qq)
            want = F / N
            lim = (2 * c - 1) / (2 * c + 1) * tn
            close(f"cylinder {model}: mu_min over the run = F/N at the end (closed form q(s))", r_["mu"], want, rel=1e-6)
            print(f"     ... limit as r -> oo: {(2*c-1)/(2*c+1):.4f} tan = {lim:.6f}")
        else:
            want = (G / 3) / (C + b * G / (3 * PI * r0))
            close(f"cylinder {model}: mu_min = value at the start tan/(3 + b tan/(pi r0))", r_["mu"], want, rel=1e-9)
    for model in ("energy", "energy-thin", "lagrangian-printed", "quasi-circular-lift"):
        body = Body("cylinder", b, r0)
        G, C = res[("cylinder", model)]["G"], res[("cylinder", model)]["C"]
        a0 = accel(model, body, 0.0, 0.0, G, C)
        n0, f0 = forces(model, body, 0.0, 0.0, a0, G, C)
        close(f"cylinder {model}: mu_min = F/N at the start (lift models, from rest)", res[("cylinder", model)]["mu"], f0 / n0, rel=1e-9)
    with open(os.path.join(REF, "circular_mu_min.csv"), "w") as fh:
        fh.write("# made by scripts/derivations/circular_numerics.py; alpha 30 deg, b 0.01 m, r0 0.1 m, g 9.81, from rest, t_end 100 s\n")
        fh.write("# mu_min = max over the run of |F|/N (RK4 dt 1e-3, every step); sphere swath w = 2r\n")
        fh.write("shape,model,alias,mu_min,t_of_max_s,min_n_over_mg,x_end_m,v_end_m_s,a_end_over_g_sin\n")
        for shape, model, r_ in rows:
            fh.write(f"{shape},{model},{ALIAS.get(model, 'eq95')},{r_['mu']:.10g},{r_['t_mu']:.4f},{r_['nmin']:.10g},"
                     f"{r_['x']:.10g},{r_['v']:.10g},{r_['a'] / r_['G']:.10g}\n")

    # reference states for the implementers' tests: a, N/M, F/M at (x, v)
    with open(os.path.join(REF, "circular_forces.csv"), "w") as fh:
        fh.write("# made by scripts/derivations/circular_numerics.py; per unit mass (m/s^2); alpha 30 deg, g 9.81, b 0.01, r0 0.1\n")
        fh.write("# N/M = C + (lam r' + r'') v^2 + r' a ; F/M = G - a - lam v^2 (F positive up the slope); lam = M'/M\n")
        fh.write("shape,model,x_m,v_m_s,a_m_s2,normal_over_m,friction_over_m,friction_ratio\n")
        G, C = 9.81 * 0.5, 9.81 * math.cos(math.radians(30))
        for shape in ("cylinder", "sphere"):
            body = Body(shape, b, r0)
            for model in ("snowless",) + MODELS:
                for x, v in ((0.0, 0.0), (0.0, 3.0), (1.0, 2.0), (50.0, 8.0), (5000.0, 60.0)):
                    a = accel(model, body, x, v, G, C)
                    n, f = forces(model, body, x, v, a, G, C)
                    fh.write(f"{shape},{model},{x},{v},{a:.15g},{n:.15g},{f:.15g},{abs(f) / n:.15g}\n")
    check("reference CSVs written", True)

    print("== losses: snowless cylinder with drag reaches v_t; accreting log does not")
    body = Body("cylinder", 0.0, r0)
    G, C = 9.81 * 0.5, 9.81 * math.cos(math.radians(30))
    loss = (1.0, 1.2, 0.0, 0.0)
    m = body.mass(r0)
    vt = math.sqrt(m * G / (0.5 * 1.2 * 1.0 * body.area(r0)))
    tau = 1.5 * vt / G
    x, v, t, dt = 0.0, 0.0, 0.0, 1e-3
    f = lambda x_, v_: (v_, accel("snowless", body, x_, v_, G, C, loss))  # noqa: E731
    while t < 20.0 - 1e-12:
        k1 = f(x, v)
        k2 = f(x + dt / 2 * k1[0], v + dt / 2 * k1[1])
        k3 = f(x + dt / 2 * k2[0], v + dt / 2 * k2[1])
        k4 = f(x + dt * k3[0], v + dt * k3[1])
        x += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        v += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        t += dt
    close("snowless cylinder + drag: v(20 s) = v_t tanh(t/tau) (RK4, 1e-10)", v, vt * math.tanh(t / tau), rel=1e-10)
    close("snowless cylinder + drag: x(20 s) = tau v_t ln cosh(t/tau)", x, tau * vt * math.log(math.cosh(t / tau)), rel=1e-10)
    print(f"     v_t = {vt:.6f} m/s (rho 400, r0 0.1, C_d 1, rho_a 1.2, 30 deg), tau = {tau:.4f} s")
    # accreting log (eq. 4) with drag: v^2/(K r) -> 1 with K = pi rho G/(rho_a C_d), slowly
    body = Body("cylinder", b, r0)
    x, v, t, dt = 0.0, 0.0, 0.0, 2e-3
    f = lambda x_, v_: (v_, accel("torque-cm", body, x_, v_, G, C, loss))  # noqa: E731
    K = PI * 400 * G / 1.2
    rx = 1.5 * 7 / 6 * 400 * b / 1.2
    D = 1.2 / (PI * 400 * 1.5)
    checkpoints = {}
    for t_mark in (100.0, 1000.0, 5000.0):
        while t < t_mark - 1e-9:
            k1 = f(x, v)
            k2 = f(x + dt / 2 * k1[0], v + dt / 2 * k1[1])
            k3 = f(x + dt / 2 * k2[0], v + dt / 2 * k2[1])
            k4 = f(x + dt * k3[0], v + dt * k3[1])
            x += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            v += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
            t += dt
        r = math.sqrt(r0**2 + b * x / PI)
        pred = K * (r - rx - b / (4 * PI * D))
        checkpoints[t_mark] = (r, v, v * v / (K * r), v * v / pred)
        print(f"     eq. (4) + drag, t = {t_mark:6.0f} s: r = {r:8.3f} m, v = {v:8.3f} m/s, v^2/(K r) = {v*v/(K*r):.5f}, "
              f"v^2/(K (r - r_x - b/(4 pi D))) = {v*v/pred:.6f}")
    check("eq. (4) + drag: v keeps growing (no terminal velocity)", checkpoints[5000.0][1] > checkpoints[1000.0][1] > checkpoints[100.0][1])
    close("eq. (4) + drag: v^2 -> K (r - r_x - b/(4 pi D)) at large r (1e-2)", checkpoints[5000.0][3], 1.0, rel=1e-2)
    finish()


if __name__ == "__main__":
    main()
