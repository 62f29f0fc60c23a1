"""Contact forces N and F of every model (docs/contact-forces.md §§1-3).

Conventions: x down the slope, y normal to it (up); gravity per unit mass
(G, -C) with G = g sin(alpha), C = g cos(alpha). The contact force on the body
is (-F, N): N normal (positive pushing away from the slope), F friction
positive UP the slope. Snow joins at rest, so the external force is dp/dt with
p the momentum of the body:  N = dp_y/dt + M C,  F = M G - dp_x/dt.

Run: python3 scripts/derivations/contact_forces.py   (exits 1 on any FAIL)
"""

import sympy as sp

from _check import check, finish, same, series_zero

x, v, a, b, r0, g, al, rho, l = sp.symbols("x v a b r0 g alpha rho l", positive=True)
G, C = sp.symbols("G C", positive=True)  # g sin(alpha), g cos(alpha)
pi = sp.pi

# ---------------------------------------------------------------- circular models
print("== circular models (§2): p = M (v, dr/dt)")
r = sp.sqrt(r0**2 + b * x / pi)  # eq. (8)
M = pi * rho * l * r**2
q = b * v**2 / (pi * r**2)  # momentum-drag group b v^2/(pi r^2)


def ddt(expr):
    """d/dt along x' = v, v' = a (a is the model's acceleration)."""
    return sp.diff(expr, x) * v + sp.diff(expr, v) * a


rdot = ddt(r)
same("eq. (1): dr/dt = b v/(2 pi r)", rdot, b * v / (2 * pi * r))
same("eq. (1): dm/dt = m b v/(pi r^2)", ddt(M), M * b * v / (pi * r**2))
N_circ = ddt(M * rdot) + M * C
F_circ = M * G - ddt(M * v)
N_circ_form = C + b * a / (2 * pi * r) + b**2 * v**2 / (4 * pi**2 * r**3)
F_circ_form = G - a - q
same("circular N/M = C + b a/(2 pi r) + b^2 v^2/(4 pi^2 r^3)", N_circ / M, N_circ_form)
same("circular F/M = G - a - b v^2/(pi r^2)", F_circ / M, F_circ_form)
same("circular N/M = C + (b/(2 pi r)) (a + q/2)", N_circ_form, C + b / (2 * pi * r) * (a + q / 2))

# snowless limit (App. A): b = 0, a = 2G/3
same("snowless: N = m C exactly", N_circ_form.subs(b, 0), C)
same("snowless: F = m G/3 exactly", F_circ_form.subs({b: 0, a: 2 * G / 3}), G / 3)

# eq. (4) is momentum + torque about the centre: F from momentum equals r F = d(m r v/2)/dt
a4 = 2 * G / 3 - sp.Rational(7, 6) * q
F_torque_cm = ddt(M * r * v / 2) / r
same("eq. (4): F(momentum) = F(torque about centre)", (F_circ - F_torque_cm).subs(a, a4), 0)


# the other models violate the torque balance about the centre; the defect per unit mass:
def coeff_accel(cv, lam1, lam2, kap):
    return (2 * G / 3 - cv * q - C * (lam1 * b / (pi * r) + lam2 * b**2 / (3 * pi * r**2))) / (
        1 + kap * b**2 / (6 * pi**2 * r**2)
    )


MODELS = {
    "eq. (4)": (sp.Rational(7, 6), 0, 0, 0),
    "eq. (6)": (sp.Rational(3, 2), 0, 0, 0),
    "eq. (14)": (sp.Rational(1, 2), 1, 1, 1),
    "eq. (15)": (sp.Rational(1, 2), 1, 0, 0),
    "eq. (21) printed": (1, 1, 1, 1),
    "eq. (32)": (sp.Rational(1, 2), 0, 0, 0),
    "eq. (32)+(36)": (sp.Rational(1, 2), 1, 0, 0),
}
defect_want = {
    "eq. (4)": 0,
    "eq. (6)": q / 2,
    "eq. (32)": -q,
}
same("(F_mom - F_torque_cm)/M = G - (3/2) a - (7/4) q for any a", (F_circ - F_torque_cm) / M, G - sp.Rational(3, 2) * a - sp.Rational(7, 4) * q)
for name, co in MODELS.items():
    am = coeff_accel(*co)
    d = ((F_circ - F_torque_cm) / M).subs(a, am)
    if name in defect_want:
        same(f"{name}: (F_mom - F_torque_cm)/M = {defect_want[name]}", d, defect_want[name])

# drag-only models: F/M = G/3 + (c-1) q ; N/M = C + (b/2 pi r)(2G/3 + (1/2 - c) q)
cv = sp.symbols("c_v", positive=True)
a_drag = 2 * G / 3 - cv * q
same("drag-only: F/M = G/3 + (c_v - 1) q", F_circ_form.subs(a, a_drag), G / 3 + (cv - 1) * q)
same(
    "drag-only: N/M = C + (b/(2 pi r))(2G/3 + (1/2 - c_v) q)",
    N_circ_form.subs(a, a_drag),
    C + b / (2 * pi * r) * (2 * G / 3 + (sp.Rational(1, 2) - cv) * q),
)
# closed form from rest: u = v^2 = A s (1 - (s0/s)^(1+2c)), s = pi r^2, A = 4G/(3b(1+2c))
s, s0 = sp.symbols("s s0", positive=True)
A = 4 * G / (3 * b * (1 + 2 * cv))
u = A * s * (1 - (s0 / s) ** (1 + 2 * cv))
same("drag-only from rest: du/ds = 4G/(3b) - 2 c_v u/s", sp.diff(u, s), 4 * G / (3 * b) - 2 * cv * u / s)
same("drag-only from rest: u(s0) = 0", u.subs(s, s0), 0)
q_of_s = b * u / s
qinf = sp.limit(q_of_s.subs(cv, sp.Rational(7, 6)), s, sp.oo)
same("eq. (4): q -> 2 a_inf = 2G/5", qinf, 2 * G / 5)
for name, c_val, ratio in [
    ("eq. (4)", sp.Rational(7, 6), sp.Rational(2, 5)),
    ("eq. (6)", sp.Rational(3, 2), sp.Rational(1, 2)),
    ("eq. (32)", sp.Rational(1, 2), 0),
]:
    F_inf = sp.limit((G / 3 + (c_val - 1) * q_of_s).subs(cv, c_val), s, sp.oo)
    same(f"{name}: F/(M G) -> (2c-1)/(2c+1) = {ratio}", F_inf / G, ratio)
# eq. (32): F/M = (G/3)(s0/s)^2 exactly from rest, decreasing
same(
    "eq. (32) from rest: F/M = (G/3)(s0/s)^2",
    (G / 3 + (cv - 1) * q_of_s).subs(cv, sp.Rational(1, 2)),
    G / 3 * (s0 / s) ** 2,
)

# ---------------------------------------------------------------- turn models
print("== turn models (§3): disk r + annular sector r<r'<r+b over [0, theta], rigid rotation about C")
th, w, wd = sp.symbols("theta omega omegadot", real=True)  # theta, theta', theta''
rp, tp = sp.symbols("rp tp", positive=True)  # r', theta'
D = {n: (r0 + b) ** n - r0**n for n in (2, 3, 4)}
rl = rho * l
# element relative to the contact line C = (x, 0): (-r' sin t', r0 - r' cos t')
X = -rp * sp.sin(tp)
Y = r0 - rp * sp.cos(tp)
# rigid rotation about C, clockwise at rate w: velocity w (Y, -X)
vx, vy = w * Y, -w * X


def body_integral(f):
    disk = sp.integrate(sp.integrate(f * rp, (tp, 0, 2 * pi)), (rp, 0, r0))
    sector = sp.integrate(sp.integrate(f * rp, (tp, 0, th)), (rp, r0, r0 + b))
    return sp.simplify(rl * (disk + sector))


Mb = body_integral(1)
Sx = body_integral(X)
Sy = body_integral(Y)
IC = body_integral(X**2 + Y**2)
Q = rl * D[3] / 3
same("M = rho l (pi r^2 + theta D2/2)", Mb, rl * (pi * r0**2 + th * D[2] / 2))
same("S_x = M (x_cm - x) = -Q (1 - cos theta), Q = rho l D3/3", Sx, -Q * (1 - sp.cos(th)))
same("S_y = M y_cm = M r - Q sin theta", Sy, Mb * r0 - Q * sp.sin(th))
same(
    "I_C exact (turn-model.md)",
    IC,
    rl * (sp.Rational(3, 2) * pi * r0**4 + th * (r0**2 * D[2] / 2 + D[4] / 4) - sp.Rational(2, 3) * r0 * D[3] * sp.sin(th)),
)
px = body_integral(vx)
py = body_integral(vy)
same("p_x = theta' S_y  (p = M omega x (r_cm - r_C))", px, w * Sy)
same("p_y = -theta' S_x = theta' Q (1 - cos theta)", py, w * Q * (1 - sp.cos(th)))

# the cm velocity is NOT p/M for the accreting body:
xcm = Sx / Mb  # relative to the contact line, which moves at r0 theta'
ycm = Sy / Mb
dth = lambda e: sp.diff(e, th) * w  # noqa: E731
xcm_dot = r0 * w + dth(xcm)
ycm_dot = dth(ycm)
Mdot = dth(Mb)
# errata §2 item 3: xdot_cm = P/M + (Mdot/M)(x_contact - x_cm); here x_contact - x_cm = -xcm, y_contact - y_cm = -ycm
same("xdot_cm = p_x/M + (Mdot/M)(x_C - x_cm)", xcm_dot, px / Mb + Mdot / Mb * (-xcm))
# in y the snow joins over -b < y < 0 (the radial edge t' = 0), centroid y_join = r - (2/3) D3/D2:
y_join = r0 - sp.Rational(2, 3) * D[3] / D[2]
same("ydot_cm = p_y/M + (Mdot/M)(y_join - y_cm), y_join = r - 2 D3/(3 D2)", ycm_dot, py / Mb + Mdot / Mb * (y_join - ycm))


def ddt_turn(e):
    return sp.diff(e, th) * w + sp.diff(e, w) * wd


Nt = ddt_turn(py) + Mb * C
Ft = Mb * G - ddt_turn(px)
same("N = M C + Q [theta'' (1 - cos) + theta'^2 sin]", Nt, Mb * C + Q * (wd * (1 - sp.cos(th)) + w**2 * sp.sin(th)))
same(
    "F = M G - theta'' (M r - Q sin) - theta'^2 (M' r - Q cos),  M' = dM/dtheta",
    Ft,
    Mb * G - wd * (Mb * r0 - Q * sp.sin(th)) - w**2 * (sp.diff(Mb, th) * r0 - Q * sp.cos(th)),
)

# second route: dp/dt = integral of element accelerations over the body + momentum flux of the
# snow that joins at the contact (it joins along t' = 0, r0 < r' < r0+b, with the body's velocity there)
ax = r0 * wd - rp * wd * sp.cos(tp) + rp * w**2 * sp.sin(tp)
ay = rp * wd * sp.sin(tp) + rp * w**2 * sp.cos(tp)
flux_x = sp.integrate(rl * rp * w * (vx.subs(tp, 0)), (rp, r0, r0 + b))
flux_y = sp.integrate(rl * rp * w * (vy.subs(tp, 0)), (rp, r0, r0 + b))
same("dp_x/dt = int a_x dm + joining flux (two routes agree)", body_integral(ax) + flux_x, ddt_turn(px))
same("dp_y/dt = int a_y dm + joining flux (two routes agree)", body_integral(ay) + flux_y, ddt_turn(py))
same("joining flux_x = rho l theta'^2 (r D2/2 - D3/3) (snow below C jerked backwards)", flux_x, rl * w**2 * (r0 * D[2] / 2 - D[3] / 3))

# coefficient form (per unit m_k) with the code's InTurnCoefficients mu, e1, e2
mk = pi * rl * r0**2
mu_ex = D[2] / (2 * pi * r0**2)
e1_ex = D[2] / (2 * pi * r0)
e2_ex = D[3] / (3 * pi * r0**2)
Nform = (1 + mu_ex * th) * C + e2_ex * (wd * (1 - sp.cos(th)) + w**2 * sp.sin(th))
Fform = (1 + mu_ex * th) * G - wd * (r0 * (1 + mu_ex * th) - e2_ex * sp.sin(th)) - w**2 * (e1_ex - e2_ex * sp.cos(th))
same("exact: N/m_k = (1+mu th) C + e2 [th'' (1-cos) + th'^2 sin]", Nt / mk, Nform)
same("exact: F/m_k = (1+mu th) G - th'' (r(1+mu th) - e2 sin) - th'^2 (e1 - e2 cos)", Ft / mk, Fform)
same("mu r = e1 (both variants)", mu_ex * r0, e1_ex)
# the remaining exact coefficients of the code's common form (I/m_k, W/m_k), re-derived here
c1_ex = (r0**2 * D[2] / 2 + D[4] / 4) / (pi * r0**2)
c2_ex = 2 * D[3] / (3 * pi * r0)
e3_ex = D[2] * (2 * r0 + b) / (4 * pi * r0**2)
same("I_C/m_k = 3r^2/2 + c1 th - c2 sin th", IC / (pi * rl * r0**2), sp.Rational(3, 2) * r0**2 + c1_ex * th - c2_ex * sp.sin(th))
# paper variant = first order in b of the same
Npaper = (1 + b * th / (pi * r0)) * C + b / pi * (wd * (1 - sp.cos(th)) + w**2 * sp.sin(th))
Fpaper = (1 + b * th / (pi * r0)) * G - wd * (r0 + b * th / pi - b / pi * sp.sin(th)) - w**2 * b / pi * (1 - sp.cos(th))
series_zero("paper N/m_k = exact to O(b^2)", Nform - Npaper, b, 2)
series_zero("paper F/m_k = exact to O(b^2)", Fform - Fpaper, b, 2)
same("b -> 0: N/m = C", Nform.subs(b, 0), C)
same("b -> 0 with a = r theta'' = 2G/3: F/m = G/3", Fform.subs(b, 0).subs(wd, 2 * G / (3 * r0)), G / 3)

# angular momentum about the lab-fixed point that coincides with C: dL/dt = torque of gravity
# gives I_C th'' + (I_C' - r Q (1 - cos)) th'^2 = S_y G + S_x C  (contact force has no arm)
LC = -w * IC
dLP = ddt_turn(LC) + r0 * w * py  # dL_P/dt = dL_C/dt + v_C x p  (v_C = r th' x-hat)
tauP = Sx * (-C) - Sy * G
eom_L = sp.expand(-(dLP - tauP))  # = I_C th'' + (...) th'^2 - (S_y G + S_x C)
same(
    "angular-momentum EOM: I_C th'' + (I_C' - r Q(1-cos)) th'^2 = S_y G + S_x C",
    eom_L,
    IC * wd + (sp.diff(IC, th) - r0 * Q * (1 - sp.cos(th))) * w**2 - (Sy * G + Sx * C),
)
# energy EOM: I_C th'' + I_C'/2 th'^2 = -V'(theta), V of turn-model.md
m_s = rl * th * D[2] / 2
Vb = C * (Mb * ycm - mk * r0 + m_s * b / 2) - G * (Mb * (xcm + r0 * th) - m_s * r0 * th / 2)
same(
    "V/m_k = -G(r th + e1 th^2/2 - e2 (1-cos)) + C(e3 th - e2 sin)",
    Vb / mk,
    -G * (r0 * th + e1_ex * th**2 / 2 - e2_ex * (1 - sp.cos(th))) + C * (e3_ex * th - e2_ex * sp.sin(th)),
)
eom_E = IC * wd + sp.diff(IC, th) / 2 * w**2 + sp.diff(Vb, th)
same(
    "torque EOM - energy EOM = b^3 rho l (3 b th'^2 + 2 C + 4 r th'^2)/24 (errata §2 item 3)",
    sp.expand(eom_L - eom_E),
    b**3 * rl * (3 * b * w**2 + 2 * C + 4 * r0 * w**2) / 24,
)

# ---------------------------------------------------------------- late turns
print("== late turns: v_beg^2 ~ A k^2, theta'^2 -> A/b^2")
k = sp.symbols("k", positive=True)
Au, Bu, Cu = sp.symbols("A_u B_u C_u")
eps = sp.symbols("epsilon", positive=True)  # 1/k


def next_u(uk, rk, bb, charge, beta_exact=True):
    """One turn of the paper model + collision (89): u -> u' (u = v^2 at the start)."""
    vend2 = (sp.Rational(3, 2) * uk + 4 * pi * G * (rk + bb) - 4 * bb * C) / (sp.Rational(3, 2) + 4 * bb / rk)
    R = rk + bb
    fac = (R**2 + 2 * rk**2) / (3 * rk * R)
    return vend2 * fac**2 - charge


for label, charge in [("note", 0), ("charged", sp.Rational(4, 3) * C * b)]:
    uk = Au * k**2 + Bu * k + Cu
    uk1 = Au * (k + 1) ** 2 + Bu * (k + 1) + Cu
    rk = r0 + k * b
    res = sp.series((next_u(uk, rk, b, charge) - uk1).subs(k, 1 / eps), eps, 0, 1).removeO()
    res = sp.expand(res)
    c_m1 = res.coeff(eps, -1)
    c_0 = res.coeff(eps, 0)
    solA = sp.solve(c_m1, Au)
    sol = sp.solve([c_m1, c_0], [Au, Bu], dict=True)
    check(f"{label}: A = pi G b/2 (u_k ~ A k^2)", len(solA) == 1 and sp.simplify(solA[0] - pi * G * b / 2) == 0, str(solA))
    B_sol = sp.simplify(sol[0][Bu])
    print(f"     {label}: A = {sp.simplify(sol[0][Au])},  B = {sp.factor(B_sol)}")
    # (b/pi) theta'^2 at the start of turn k = (b/pi) u/r_k^2 = G/2 + (b/r_k) D1 + O(r_k^-2)
    rr = sp.symbols("r_k", positive=True)
    u_r = (pi * G * b / 2) * ((rr - r0) / b) ** 2 + B_sol * (rr - r0) / b
    D1 = sp.limit((b / pi * u_r / rr**2 - G / 2) * rr / b, rr, sp.oo)
    D1_want = {"note": -(24 * C + 14 * pi * G) / (39 * pi), "charged": -(36 * C + 14 * pi * G) / (39 * pi)}[label]
    same(f"{label}: (b/pi) theta0'^2 = G/2 + (b/r_k) D1, D1 = {D1_want}", D1, D1_want)
    # N at theta = 3 pi/2 to O(b/r_k) with the paper in-turn energy integral (min to this order)
    th0sq = pi * G / (2 * b) + pi * D1 / rr
    Ik = sp.Rational(3, 2) * rr**2 + 2 * b * rr / pi * (th - sp.sin(th))
    Wk = -G * (rr * th + b / pi * (th**2 / 2 - 1 + sp.cos(th))) + C * b / pi * (th - sp.sin(th))
    w2k = (sp.Rational(3, 2) * rr**2 * th0sq - 2 * Wk) / Ik
    thddk = (-sp.diff(Wk, th) - sp.diff(Ik, th) * w2k / 2) / Ik
    Nk = (1 + b * th / (pi * rr)) * C + b / pi * (thddk * (1 - sp.cos(th)) + w2k * sp.sin(th))
    Nk_min = Nk.subs(th, 3 * pi / 2)
    eps_r = sp.symbols("eps_r", positive=True)  # b/r_k
    n1 = sp.simplify(sp.series(Nk_min.subs(rr, b / eps_r), eps_r, 0, 2).removeO())
    n1_want = {
        "note": C - G / 2 + eps_r * (C * (sp.Rational(3, 2) + 8 / (13 * pi)) + G * (1 / pi + sp.Rational(14, 39) - 1)),
        "charged": C - G / 2 + eps_r * (C * (sp.Rational(3, 2) + 12 / (13 * pi)) + G * (1 / pi + sp.Rational(14, 39) - 1)),
    }[label]
    same(f"{label}: N(3pi/2)/m_k = C - G/2 + (b/r_k)(c_C C + c_G G) + O((b/r_k)^2)", n1, n1_want)

# general collision law v'^2 = v_end^2 (1 - gamma b/r): A = (8 pi/3) G b/(14/3 + gamma), kappa = b th'^2/(pi G)
gam = sp.symbols("gamma", positive=True)  # collision loss: v^2 -> v^2 (1 - gamma b/r), docs/turn-model.md
A_gen = 8 * pi * G * b / 3 / (sp.Rational(14, 3) + gam)
kappa = sp.simplify(A_gen / (pi * b * G))
same("kappa = (b/pi) th'^2/G -> 8/(14 + 3 gamma), gamma = collision loss v^2 -> v^2 (1 - gamma b/r)", kappa, 8 / (14 + 3 * gam))
same("note collision: gamma = 2/3", sp.series(((((r0 + b) ** 2 + 2 * r0**2) / (3 * r0 * (r0 + b))) ** 2 - 1) / (b / r0), b, 0, 1).removeO(), -sp.Rational(2, 3))
same("kappa(2/3) = 1/2", kappa.subs(gam, sp.Rational(2, 3)), sp.Rational(1, 2))
same("mean a with collisions = 4G/(14 + 3 gamma) -> G/4", (4 / (14 + 3 * gam)).subs(gam, sp.Rational(2, 3)), sp.Rational(1, 4))
same(
    "mean a in-turn (2/3 - 2 kappa/3) G -> G/3, with collisions minus gamma kappa G/4",
    sp.Rational(2, 3) - 2 * kappa / 3 - gam * kappa / 4,
    4 / (14 + 3 * gam),
)

# late-turn forces, leading order: th'^2 = kappa pi G/b, a = r th'' from eq. (73)
kap = sp.symbols("kappa", positive=True)
w2 = kap * pi * G / b
rk = sp.symbols("r_k", positive=True)
I0 = sp.Rational(3, 2) * rk**2 + 2 * b * rk / pi * (th - sp.sin(th))
dI = 2 * b * rk / pi * (1 - sp.cos(th))
dW = -G * (rk + b / pi * th - b / pi * sp.sin(th)) + C * b / pi * (1 - sp.cos(th))
thdd = (-dW - dI * w2 / 2) / I0
N_late = (1 + b * th / (pi * rk)) * C + b / pi * (thdd * (1 - sp.cos(th)) + w2 * sp.sin(th))
F_late = (1 + b * th / (pi * rk)) * G - thdd * (rk + b * th / pi - b / pi * sp.sin(th)) - w2 * b / pi * (1 - sp.cos(th))
N_lim = sp.limit(N_late, rk, sp.oo)
F_lim = sp.limit(F_late, rk, sp.oo)
a_lim = sp.limit(rk * thdd, rk, sp.oo)
same("late: a -> 2G/3 - (2 kappa/3) G (1 - cos) [eq. (77)]", a_lim, 2 * G / 3 - 2 * kap * G / 3 * (1 - sp.cos(th)))
same("late: N/m -> C + kappa G sin(theta)", N_lim, C + kap * G * sp.sin(th))
same("late: F/m -> G/3 - (kappa/3) G (1 - cos theta)", F_lim, G / 3 - kap * G / 3 * (1 - sp.cos(th)))
same("note (kappa=1/2): F/m -> (G/6)(1 + cos theta)", F_lim.subs(kap, sp.Rational(1, 2)), G / 6 * (1 + sp.cos(th)))
# hop: min over theta of C + kappa G sin = C - kappa G  ->  tan(alpha) > 1/kappa = 2
check("hop (late, note): critical tan(alpha) = 2, alpha* = 63.435 deg", abs(float(sp.deg(sp.atan(2))) - 63.43494882) < 1e-6)
# max |F|/N over a late turn (kappa = 1/2): (tan/6)(1+cos)/(1 + (tan/2) sin) -> max at tan(theta/2) = -tan/2
tau = sp.symbols("tau", positive=True)  # tan(alpha)/2
f = (1 + sp.cos(th)) / (1 + tau * sp.sin(th))
th_star = 2 * pi - 2 * sp.atan(tau)
same("max of (1+cos)/(1+tau sin): stationary at theta = 2 pi - 2 atan(tau)", sp.diff(f, th).subs(th, th_star), 0)
same("... value 2/(1 - tau^2)", f.subs(th, th_star), 2 / (1 - tau**2))
T = sp.symbols("T", positive=True)  # tan(alpha)
mu_late = T / 6 * (2 / (1 - (T / 2) ** 2))
same("late-turn mu_min = 4 tan/(3 (4 - tan^2))", mu_late, 4 * T / (3 * (4 - T**2)))
print(f"     30 deg: mu_min(late) = {float(mu_late.subs(T, sp.tan(sp.pi / 6))):.10f} ; snowless tan/3 = {float(sp.tan(sp.pi/6)/3):.10f}")

finish()
