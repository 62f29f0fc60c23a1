"""The snowball (docs/snowball-and-losses.md §1): every circular derivation of §2 redone for a
body with I = k M r^2, mass M(r) and swath width w; the cylinder reproduces eqs. (4), (6), (14),
(15), (21) printed, (32), (32)+(36); the sphere with w = 2r gives the terminal fractions
1/6, 1/7, 2/7, 2/7, 5/28 and 5/7 without snow; the torque-about-centre sphere is the closed form
of the letter in The Physics Teacher 57, 436 (2019).

Run: python3 scripts/derivations/sphere.py   (exits 1 on any FAIL)
"""

import csv
import os

import sympy as sp

from _check import check, close, finish, same

x, v, a, b, r0, rho, l = sp.symbols("x v a b r0 rho l", positive=True)
G, C, g, al = sp.symbols("G C g alpha", positive=True)
kI = sp.symbols("k", positive=True)
pi = sp.pi
HERE = os.path.dirname(os.path.abspath(__file__))


def derivations(M, r, k):
    """Accelerations a(x, v) of every circular derivation for a body of mass M(x), radius r(x),
    I = k M r^2, picking up snow at rest from the slab -b < y < 0 (centroid -b/2).
    lam = M'/M (per metre), rp = r', rpp = r''."""
    lam = sp.diff(M, x) / M
    rp = sp.diff(r, x)
    rpp = sp.diff(r, x, 2)

    def ddt(e):
        return sp.diff(e, x) * v + sp.diff(e, v) * a

    out = {}
    # momentum + torque about the centre: M G - F = d(M v)/dt, r F = d(k M r^2 v/r)/dt
    F = sp.symbols("F")
    sol = sp.solve([sp.Eq(M * G - F, ddt(M * v)), sp.Eq(r * F, ddt(k * M * r * v))], [a, F], dict=True)[0]
    out["torque-cm"] = sp.simplify(sol[a])
    # torque about the contact line: r M G = d((1+k) M r v)/dt
    out["torque-contact"] = sp.simplify(sp.solve(sp.Eq(r * M * G, ddt((1 + k) * M * r * v)), a)[0])
    # energy: T = M(1+k) v^2/2 + M (r' v)^2/2 ; V' = M' C (r + b/2) + M r' C - M G
    Me = M * (1 + k + rp**2)
    Vp = sp.diff(M, x) * C * (r + b / 2) + M * rp * C - M * G
    out["energy"] = sp.simplify(sp.solve(sp.Eq(Me * a + sp.diff(Me, x) * v**2 / 2, -Vp), a)[0])
    # Lagrangian as printed: d/dt(dT/dv) = -dV/dx, omitting dT/dx
    out["lagrangian-printed"] = sp.simplify(sp.solve(sp.Eq(Me * a + sp.diff(Me, x) * v**2, -Vp), a)[0])
    # §2.4: T = (1+k) M v^2/2, dV/dt = -M G v
    out["quasi-circular"] = sp.simplify(G / (1 + k) - lam * v**2 / 2)
    out["quasi-circular-lift"] = sp.simplify(G / (1 + k) - lam * v**2 / 2 - C * (lam * r + rp) / (1 + k))
    # energy to first order in b (eq. (15) form): drop the r'^2 inertia and the b^2 lift
    out["energy-thin"] = sp.simplify((G - lam * (1 + k) * v**2 / 2 - C * (lam * r + rp)) / (1 + k))
    # contact forces from the momentum balance, p = M (v, r' v)
    N = sp.simplify((ddt(M * rp * v) + M * C) / M)
    Fm = sp.simplify((M * G - ddt(M * v)) / M)
    return out, N, Fm, lam, rp, rpp


print("== generic derivations reproduce the note for the cylinder (I = m r^2/2, m = pi rho l r^2)")
r_cyl = sp.sqrt(r0**2 + b * x / pi)
M_cyl = pi * rho * l * r_cyl**2
cyl, N_cyl, F_cyl, *_ = derivations(M_cyl, r_cyl, sp.Rational(1, 2))
q = b * v**2 / (pi * r_cyl**2)
note = {
    "torque-cm": 2 * G / 3 - sp.Rational(7, 6) * q,  # eq. (4)
    "torque-contact": 2 * G / 3 - sp.Rational(3, 2) * q,  # eq. (6)
    "energy": (2 * G / 3 - q / 2 - C * (3 * b * r_cyl + b**2) / (3 * pi * r_cyl**2)) / (1 + b**2 / (6 * pi**2 * r_cyl**2)),  # (14)
    "energy-thin": 2 * G / 3 - q / 2 - g * 0 - C * b / (pi * r_cyl),  # eq. (15)
    "lagrangian-printed": (2 * G / 3 - q - C * (3 * b * r_cyl + b**2) / (3 * pi * r_cyl**2)) / (1 + b**2 / (6 * pi**2 * r_cyl**2)),
    "quasi-circular": 2 * G / 3 - q / 2,  # eq. (32)
    "quasi-circular-lift": 2 * G / 3 - q / 2 - C * b / (pi * r_cyl),  # (32)+(36)
}
for name, want in note.items():
    same(f"cylinder {name} reproduces the note", cyl[name], want)

print("== the sphere, swath w = 2r: I = 2 M r^2/5, M = (4/3) pi rho r^3, dM/dx = rho b w")
rs = sp.Function("r")(x)
# radius law from dM/dx = rho b w: 4 pi rho r^2 r' = rho b w
w_sw = sp.symbols("w", positive=True)
rprime_general = sp.solve(sp.Eq(4 * pi * rho * rs**2 * sp.Derivative(rs, x), rho * b * w_sw), sp.Derivative(rs, x))[0]
same("sphere: dr/dx = b w/(4 pi r^2)", rprime_general, b * w_sw / (4 * pi * rs**2))
r_sph = sp.sqrt(r0**2 + b * x / pi)  # with w = 2r: pi r^2 = pi r0^2 + b x, the log's eq. (8)
same("w = 2r: pi r^2 = pi r0^2 + b x solves dr/dx = b (2r)/(4 pi r^2)", sp.diff(r_sph, x), b * 2 * r_sph / (4 * pi * r_sph**2))
# one full turn adds a shell of thickness b to first order: dr per turn = 2 pi r dr/dx = b
same("w = 2r: dr per turn (2 pi r of slope) = b", 2 * pi * r_sph * sp.diff(r_sph, x), b)
M_sph = sp.Rational(4, 3) * pi * rho * r_sph**3
sph, N_sph, F_sph, lam_s, rp_s, rpp_s = derivations(M_sph, r_sph, sp.Rational(2, 5))
qs = b * v**2 / (pi * r_sph**2)
same("sphere lam = M'/M = (3/2) b/(pi r^2)", lam_s, sp.Rational(3, 2) * b / (pi * r_sph**2))
sphere_want = {
    "torque-cm": 5 * G / 7 - sp.Rational(23, 14) * qs,
    "torque-contact": 5 * G / 7 - 2 * qs,
    "quasi-circular": 5 * G / 7 - sp.Rational(3, 4) * qs,
    "quasi-circular-lift": 5 * G / 7 - sp.Rational(3, 4) * qs - sp.Rational(10, 7) * C * b / (pi * r_sph),
    "energy-thin": 5 * G / 7 - sp.Rational(3, 4) * qs - sp.Rational(10, 7) * C * b / (pi * r_sph),
    "energy": (5 * G / 7 - sp.Rational(3, 4) * qs - sp.Rational(10, 7) * C * b / (pi * r_sph)
               - sp.Rational(15, 28) * C * b**2 / (pi * r_sph**2) - sp.Rational(5, 112) * b**3 * v**2 / (pi**3 * r_sph**4))
    / (1 + sp.Rational(5, 28) * b**2 / (pi**2 * r_sph**2)),
    "lagrangian-printed": (5 * G / 7 - sp.Rational(3, 2) * qs - sp.Rational(10, 7) * C * b / (pi * r_sph)
                           - sp.Rational(15, 28) * C * b**2 / (pi * r_sph**2) - sp.Rational(5, 56) * b**3 * v**2 / (pi**3 * r_sph**4))
    / (1 + sp.Rational(5, 28) * b**2 / (pi**2 * r_sph**2)),
}
for name, want in sphere_want.items():
    same(f"sphere {name}: {sp.sstr(want)[:90]}", sph[name], want)
same("sphere snowless (b = 0): a = 5G/7", sph["torque-cm"].subs(b, 0), 5 * G / 7)
same("sphere snowless: F = (2/7) M G, N = M C", (F_sph.subs(b, 0) - 0).subs(a, 5 * G / 7), sp.Rational(2, 7) * G)
same("sphere N/M = C + lam r' v^2 + r' a + r'' v^2", N_sph, C + lam_s * rp_s * v**2 + rp_s * a + rpp_s * v**2)
same("sphere (w=2r) N/M = C + b a/(2 pi r) + b^2 v^2/(2 pi^2 r^3)", N_sph, C + b * a / (2 * pi * r_sph) + b**2 * v**2 / (2 * pi**2 * r_sph**3))
same("sphere F/M = G - a - (3/2) b v^2/(pi r^2)", F_sph, G - a - sp.Rational(3, 2) * qs)

print("== potential energy (zero at the start; slab snow from -b/2): V = C[M r - M0 r0 + (b/2)(M - M0)] - G int_0^x M dx'")
xp = sp.symbols("xp", positive=True)
for shape, M_, r_ in (("cylinder", M_cyl, r_cyl), ("sphere", M_sph, r_sph)):
    M0 = M_.subs(x, 0)
    # direct definition: body at height r, minus start, plus the collected slab (centroid (x', -b/2))
    V_direct = M_ * (r_ * C - x * G) - M0 * r0 * C + sp.integrate((sp.diff(M_, x) * (b * C / 2 + x * G)).subs(x, xp), (xp, 0, x))
    V_form = C * (M_ * r_ - M0 * r0 + b / 2 * (M_ - M0)) - G * sp.integrate(M_.subs(x, xp), (xp, 0, x))
    same(f"{shape}: V = C[M r - M0 r0 + (b/2)(M - M0)] - G int M dx", V_direct, V_form)
same("cylinder: int_0^x M dx = rho l (pi r0^2 x + b x^2/2)", sp.integrate(M_cyl.subs(x, xp), (xp, 0, x)), rho * l * (pi * r0**2 * x + b * x**2 / 2))
same("sphere (w = 2r): int_0^x M dx = 8 pi^2 rho (r^5 - r0^5)/(15 b)", sp.integrate(M_sph.subs(x, xp), (xp, 0, x)),
     8 * pi**2 * rho * (r_sph**5 - r0**5) / (15 * b))

print("== terminal fractions a_inf/(g sin alpha), w = 2r (u = v^2 linear in s = pi r^2)")
s_, s0 = sp.symbols("s s0", positive=True)
Ainf = sp.symbols("A_inf")
frac = {}
for shape, table, M_, r_ in (("cylinder", cyl, M_cyl, r_cyl), ("sphere", sph, M_sph, r_sph)):
    for name, acc in table.items():
        # large-x: u = 2 a_inf x; substitute v^2 = 2 A x and take x -> oo
        e = acc.subs(v, sp.sqrt(2 * Ainf * x))
        lim = sp.limit(e, x, sp.oo)
        sol = sp.solve(sp.Eq(Ainf, lim), Ainf)
        frac[(shape, name)] = sp.simplify(sol[0] / G)
want_frac = {
    ("cylinder", "torque-cm"): sp.Rational(1, 5), ("cylinder", "torque-contact"): sp.Rational(1, 6),
    ("cylinder", "energy"): sp.Rational(1, 3), ("cylinder", "energy-thin"): sp.Rational(1, 3),
    ("cylinder", "lagrangian-printed"): sp.Rational(2, 9), ("cylinder", "quasi-circular"): sp.Rational(1, 3),
    ("cylinder", "quasi-circular-lift"): sp.Rational(1, 3),
    ("sphere", "torque-cm"): sp.Rational(1, 6), ("sphere", "torque-contact"): sp.Rational(1, 7),
    ("sphere", "energy"): sp.Rational(2, 7), ("sphere", "energy-thin"): sp.Rational(2, 7),
    ("sphere", "lagrangian-printed"): sp.Rational(5, 28), ("sphere", "quasi-circular"): sp.Rational(2, 7),
    ("sphere", "quasi-circular-lift"): sp.Rational(2, 7),
}
for key, want in want_frac.items():
    same(f"{key[0]} {key[1]}: a_inf/G = {want}", frac[key], want)
# general law: a_inf/G = 1/((1+k)(1 + 2 Sigma/(n - p))), M ~ r^n, w ~ r^p, Sigma the coefficient of (r'/r) v^2
n_, p_, Sig = sp.symbols("n p Sigma", positive=True)
law = 1 / ((1 + kI) * (1 + 2 * Sig / (n_ - p_)))
same("law: cylinder torque-cm (k=1/2, n=2, p=0, Sigma = n + k/(1+k))", law.subs({kI: sp.Rational(1, 2), n_: 2, p_: 0, Sig: 2 + sp.Rational(1, 3)}), sp.Rational(1, 5))
same("law: sphere torque-cm, w = 2r (k=2/5, n=3, p=1)", law.subs({kI: sp.Rational(2, 5), n_: 3, p_: 1, Sig: 3 + sp.Rational(2, 7)}), sp.Rational(1, 6))
# other swath laws for the sphere (torque about the centre): asymptotic ansatz r ~ x^(1/(3-p)), v^2 = 2 a x
for p_val, want in ((0, sp.Rational(15, 67)), (sp.Rational(1, 2), sp.Rational(25, 127))):
    got = law.subs({kI: sp.Rational(2, 5), n_: 3, p_: p_val, Sig: 3 + sp.Rational(2, 7)})
    same(f"sphere torque-cm, w ~ r^{p_val}: a_inf/G = {want}", got, want)
    # direct check: a = 5G/7 - Sigma (r'/r) v^2 with r'/r = 1/((3-p) x) and v^2 = 2 a x
    A_ = sp.symbols("A_")
    sol = sp.solve(sp.Eq(A_, 5 * G / 7 - (3 + sp.Rational(2, 7)) * 2 * A_ / (3 - p_val)), A_)[0]
    same(f"  ... direct from the asymptotic equation", sol / G, want)

print("== TPT 57, 436 (2019): sphere torque about the centre, Rubin's variables V = dr/dt, A = dV/dt")
# dr/dphi = k/(2 pi) => v = r phi' = 2 pi r V/k ; here k (the letter's symbol) = b
t = sp.symbols("t")
Vt, At, rr = sp.symbols("V A r", positive=True)
v_of = 2 * pi * rr * Vt / b
a_of = 2 * pi * (Vt**2 + rr * At) / b  # d/dt (2 pi r V/b)
eom = sp.Eq(a_of, 5 * G / 7 - sp.Rational(23, 14) * b * v_of**2 / (pi * rr**2))
lhs = sp.expand(sp.solve(eom, At)[0] * 14 * rr)
Cl = 5 * G * b / pi
same("letter's eq. (2): C - 60 V^2 = 14 r A with C = 5 g k sin(alpha)/pi", lhs, Cl - 60 * Vt**2)
V2 = Cl / 60 * (1 - (r0 / rr) ** sp.Rational(60, 7))
same("V^2(r) = (C/60)(1 - (r0/r)^(60/7)) solves 7 r d(V^2)/dr = C - 60 V^2", 7 * rr * sp.diff(V2, rr), Cl - 60 * V2)
u_s = G * s_ / (3 * b) * (1 - (s0 / s_) ** sp.Rational(30, 7))
same("v^2 = (G s/(3b)) (1 - (s0/s)^(30/7)), s = pi r^2", (v_of**2).subs(Vt, sp.sqrt(V2)).subs(rr, sp.sqrt(s_ / pi)).subs(r0, sp.sqrt(s0 / pi)), u_s)
a_s = b * sp.diff(u_s, s_) / 2
same("a(s) = (G/6)(1 + (23/7)(s0/s)^(30/7))", a_s, G / 6 * (1 + sp.Rational(23, 7) * (s0 / s_) ** sp.Rational(30, 7)))
same("a(s0) = 5G/7", a_s.subs(s_, s0), 5 * G / 7)
same("a(oo) = G/6", sp.limit(a_s, s_, sp.oo), G / 6)
same("V -> sqrt(g k sin(alpha)/(12 pi))", sp.limit(V2, rr, sp.oo), G * b / (12 * pi))
# and the ODE itself: du/dx = 2a with x = (s - s0)/b
same("u(s) satisfies the sphere torque-cm equation", b * sp.diff(u_s, s_) / 2 - (5 * G / 7 - sp.Rational(23, 14) * b * u_s / s_), 0)

# reference CSV: terminal fractions and sphere accelerations at given states (defaults: b = 0.01, r0 = 0.1, 30 deg)
ref = os.path.join(HERE, "reference", "sphere_models.csv")
with open(ref, "w", newline="") as fh:
    fh.write("# made by scripts/derivations/sphere.py; shape sphere with swath width w = 2r unless noted\n")
    fh.write("# a_m_s2 at the state (x, v) for g = 9.81, alpha = 30 deg, b = 0.01, r0 = 0.1 (density cancels)\n")
    wtr = csv.writer(fh)
    wtr.writerow(["shape", "model", "terminal_fraction", "x_m", "v_m_s", "a_m_s2", "normal_over_m_m_s2", "friction_over_m_m_s2"])
    num = {g: 9.81, al: sp.pi / 6, b: sp.Rational(1, 100), r0: sp.Rational(1, 10), rho: 400, l: 1}
    Gn, Cn = 9.81 * sp.sin(sp.pi / 6), 9.81 * sp.cos(sp.pi / 6)
    for shape, table, Nf, Ff in (("cylinder", cyl, N_cyl, F_cyl), ("sphere", sph, N_sph, F_sph)):
        for name in sorted(table):
            for xv in ((0.0, 0.0), (1.0, 2.0), (50.0, 8.0)):
                acc = table[name].subs({G: Gn, C: Cn}).subs(num).subs({x: xv[0], v: xv[1]})
                accn = float(acc)
                nn = float(Nf.subs({G: Gn, C: Cn}).subs(num).subs({x: xv[0], v: xv[1], a: accn}))
                ff = float(Ff.subs({G: Gn, C: Cn}).subs(num).subs({x: xv[0], v: xv[1], a: accn}))
                wtr.writerow([shape, name, str(want_frac[(shape, name)]), xv[0], xv[1], f"{accn:.15g}", f"{nn:.15g}", f"{ff:.15g}"])
        wtr.writerow([shape, "snowless", "5/7" if shape == "sphere" else "2/3", 0, 0,
                      f"{float((5 if shape == 'sphere' else sp.Rational(14, 3)) * Gn / 7):.15g}", f"{float(Cn):.15g}",
                      f"{float((sp.Rational(2, 7) if shape == 'sphere' else sp.Rational(1, 3)) * Gn):.15g}"])
check("reference CSV written", os.path.exists(ref))
finish()
