"""Losses, terminal velocity and the energy ledger (docs/snowball-and-losses.md §§2-3).

Losses per unit mass enter every family by G -> G - (F_d + c_rr N + F_c)/M (force/torque,
energy, Lagrangian and quasi-circular alike), with F_d = rho_a C_d A v^2/2 through the centre,
c_rr N and F_c = e_c dM/dx as couples at the contact (shifted normal force).

Run: python3 scripts/derivations/losses.py   (exits 1 on any FAIL)
"""

import math
import random

import sympy as sp

from _check import check, close, finish, same

t, x, v, a, b, r0, rho, l = sp.symbols("t x v a b r0 rho l", positive=True)
G, C, g, al = sp.symbols("G C g alpha", positive=True)
rhoa, Cd, crr, ec = sp.symbols("rho_a C_d c_rr e_c", positive=True)
kI = sp.symbols("k", positive=True)
pi = sp.pi

print("== snowless body with drag (and rolling resistance): a true terminal velocity")
r, m, A = sp.symbols("r m A", positive=True)
vt2 = 2 * m * G / (rhoa * Cd * A)
same("cylinder: v_t^2 = m g sin(a)/(rho_a C_d A/2) = pi rho r G/(rho_a C_d), A = 2 r l",
     vt2.subs({m: pi * rho * r**2 * l, A: 2 * r * l}), pi * rho * r * G / (rhoa * Cd))
same("sphere: v_t^2 = (8/3) rho r G/(rho_a C_d), A = pi r^2",
     vt2.subs({m: sp.Rational(4, 3) * pi * rho * r**3, A: pi * r**2}), sp.Rational(8, 3) * rho * r * G / (rhoa * Cd))
vt, tau, v0 = sp.symbols("v_t tau v0", positive=True)
vsol = vt * sp.tanh(t / tau + sp.atanh(v0 / vt))
# (1+k) m a = m G - rho_a C_d A v^2/2  <=>  a = (G/(1+k)) (1 - v^2/v_t^2)
expr = sp.diff(vsol, t) - (G / (1 + kI)) * (1 - vsol**2 / vt**2)
same("v(t) = v_t tanh(t/tau + atanh(v0/v_t)) with tau = (1+k) v_t/G", sp.simplify(expr.subs(tau, (1 + kI) * vt / G).rewrite(sp.exp)), 0)
xsol = tau * vt * (sp.log(sp.cosh(t / tau + sp.atanh(v0 / vt))) - sp.log(sp.cosh(sp.atanh(v0 / vt))))
same("x(t) = tau v_t ln[cosh(t/tau + atanh(v0/v_t))/cosh(atanh(v0/v_t))]", sp.simplify(sp.diff(xsol, t) - vsol), 0)
same("x(0) = 0", xsol.subs(t, 0), 0)
same("with rolling resistance: v_t^2 = 2 m (G - c_rr C)/(rho_a C_d A)", sp.solve(sp.Eq(m * (G - crr * C) - rhoa * Cd * A * v**2 / 2, 0), v**2)[0],
     2 * m * (G - crr * C) / (rhoa * Cd * A))
print("     rolling resistance alone (snowless): a = (G - c_rr C)/(1+k), constant: no terminal velocity")

print("== accreting log with drag: no terminal velocity, v^2 -> v_t(r)^2 = pi rho G r/(rho_a C_d)")
cv, D = sp.symbols("c_v D", positive=True)  # model's momentum-drag coefficient; D = drag per mass/(v^2/r) /(1+k)
u = sp.Function("u")
rr = sp.symbols("r", positive=True)
# drag-only circular models in r: dx = 2 pi r dr/b, du/dx = 2 a, a = G/(1+k) - c_v b u/(pi r^2) - D u/r
K1, L1, M1 = sp.symbols("K1 L1 M1")
ans = K1 * rr + L1 + M1 / rr
res = sp.diff(ans, rr) - (4 * pi * rr / b) * (G / (1 + kI) - cv * b * ans / (pi * rr**2) - D * ans / rr)
res = sp.expand(res * rr)  # polynomial in r and 1/r
sol = sp.solve([res.coeff(rr, 2), res.coeff(rr, 1), res.coeff(rr, 0)], [K1, L1, M1], dict=True)[0]
same("u = v^2 = K r + L + ..., K = G/((1+k) D)", sol[K1], G / ((1 + kI) * D))
same("L = -K (c_v b/(pi D) + b/(4 pi D)) = -K (r_x + b/(4 pi D))", sol[L1], -sol[K1] * (cv * b / (pi * D) + b / (4 * pi * D)))
# with a lift term -ell C b/(pi r) (energy-type models): L gains -ell C b/(pi D)
ell = sp.symbols("ell", positive=True)
resl = sp.diff(ans, rr) - (4 * pi * rr / b) * (G / (1 + kI) - cv * b * ans / (pi * rr**2) - D * ans / rr - ell * C * b / (pi * rr))
resl = sp.expand(resl * rr)
soll = sp.solve([resl.coeff(rr, 2), resl.coeff(rr, 1), resl.coeff(rr, 0)], [K1, L1, M1], dict=True)[0]
same("with lift: L = -K (r_x + b/(4 pi D)) - ell C b/(pi D)", soll[L1], -soll[K1] * (cv * b / (pi * D) + b / (4 * pi * D)) - ell * C * b / (pi * D))
Dlog = rhoa * Cd / (pi * rho * (1 + kI))
same("log: D = rho_a C_d/(pi rho (1+k)) gives K = pi rho G/(rho_a C_d)", (G / ((1 + kI) * D)).subs(D, Dlog), pi * rho * G / (rhoa * Cd))
same("log: crossover r_x = c_v b/(pi D) = (1+k) c_v rho b/(rho_a C_d)", (cv * b / (pi * D)).subs(D, Dlog), (1 + kI) * cv * rho * b / (rhoa * Cd))
Dsph = 3 * rhoa * Cd / (8 * rho * (1 + kI))
same("sphere: D = 3 rho_a C_d/(8 rho (1+k)) gives K = (8/3) rho G/(rho_a C_d)", (G / ((1 + kI) * D)).subs(D, Dsph), sp.Rational(8, 3) * rho * G / (rhoa * Cd))
print(f"     defaults (rho 400, b 0.01, rho_a 1.2, C_d 1): log eq. (4) r_x = {float((sp.Rational(3,2)*sp.Rational(7,6)*400*0.01/1.2)):.3f} m, "
      f"eq. (32) r_x = {float(sp.Rational(3,2)*sp.Rational(1,2)*400*0.01/1.2):.3f} m")
# a -> (b/(4 pi r)) du/dr -> b K/(4 pi r): no terminal acceleration either, a ~ 1/r
# time law: v^2 ~ K r, r^2 ~ b x/pi  ->  x ~ t^(4/3), v ~ t^(1/3), r ~ t^(2/3)
X0, T0 = sp.symbols("X0 T0", positive=True)
xt = X0 * t ** sp.Rational(4, 3)
same("x = X0 t^(4/3) solves x' = sqrt(K) (b x/pi)^(1/4) for X0^(3/4) = (3/4) sqrt(K) (b/pi)^(1/4)",
     sp.simplify((sp.diff(xt, t) - sp.sqrt(K1) * (b * xt / pi) ** sp.Rational(1, 4)).subs(X0, (sp.Rational(3, 4) * sp.sqrt(K1) * (b / pi) ** sp.Rational(1, 4)) ** sp.Rational(4, 3))), 0)

print("== compaction energy e_c (J/kg): an extra e_c dM/dx retarding couple")
s, s0, Kc = sp.symbols("s s0 K_c", positive=True)
Aa = 4 * G / (3 * b * (1 + 2 * cv))
# log, drag-only models: a = 2G/3 - (b/s)(c_v u + e_c/(1+k)), k = 1/2
uc = Aa * s - ec / (cv * sp.Rational(3, 2)) + Kc * s ** (-2 * cv)
same("log drag-only + compaction: u = A s - e_c/(c_v (1+k)) + K s^(-2 c_v)",
     b * sp.diff(uc, s) / 2 - (2 * G / 3 - (b / s) * (cv * uc + ec / sp.Rational(3, 2))), 0)
print("     => v^2 shifted down by a constant: a_inf unchanged; starts from rest iff e_c < G pi r0^2/b (drag-only log)")

print("== rolling resistance with accretion: a_inf = f (G - c_rr C)")
Ainf = sp.symbols("A_inf")
r_cyl = sp.sqrt(r0**2 + b * x / pi)
q = b * v**2 / (pi * r_cyl**2)
# eq. (4) + rolling resistance, N/M = C + b a/(2 pi r) + b^2 v^2/(4 pi^2 r^3) solved with a
N_over_M = C + b * a / (2 * pi * r_cyl) + b**2 * v**2 / (4 * pi**2 * r_cyl**3)
a4rr = sp.solve(sp.Eq(a, 2 * G / 3 - sp.Rational(7, 6) * q - sp.Rational(2, 3) * crr * N_over_M), a)[0]
lim = sp.limit(a4rr.subs(v, sp.sqrt(2 * Ainf * x)), x, sp.oo)
same("eq. (4) + rolling resistance: a_inf = (G - c_rr C)/5", sp.solve(sp.Eq(Ainf, lim), Ainf)[0], (G - crr * C) / 5)

print("== energy ledger of the circular models: power the model's equation injects")
# P = v [M_e a + M_e' v^2/2 + V'(x) + F_d + c_rr N + F_c]; zero for eq. (14) with the same losses
M = pi * rho * l * r_cyl**2
rp = sp.diff(r_cyl, x)
Me = M * (sp.Rational(3, 2) + rp**2)
Vp = sp.diff(M, x) * C * (r_cyl + b / 2) + M * rp * C - M * G
Fd = sp.symbols("F_d", positive=True)
Fc = ec * sp.diff(M, x)


def power(acc, with_losses):
    N = M * N_over_M.subs(a, acc)
    extra = (Fd + crr * N + Fc) if with_losses else 0
    return sp.simplify(v * (Me * acc + sp.diff(Me, x) * v**2 / 2 + Vp + extra))


inertia = 1 + b**2 / (6 * pi**2 * r_cyl**2)
a14 = (2 * G / 3 - q / 2 - C * (3 * b * r_cyl + b**2) / (3 * pi * r_cyl**2)) / inertia
same("eq. (14) lossless: P = 0 (energy conserved identically)", power(a14, False), 0)
# eq. (14) with losses: solve the energy equation with N(a) for a
a14L = sp.solve(sp.Eq(Me * a + sp.diff(Me, x) * v**2 / 2 + Vp + Fd + crr * M * N_over_M + Fc, 0), a)[0]
same("eq. (14) with drag, rolling resistance, compaction: P = 0", power(a14L, True), 0)
models = {
    "eq. (4)": 2 * G / 3 - sp.Rational(7, 6) * q,
    "eq. (6)": 2 * G / 3 - sp.Rational(3, 2) * q,
    "eq. (15)": 2 * G / 3 - q / 2 - C * b / (pi * r_cyl),
    "eq. (21) printed": (2 * G / 3 - q - C * (3 * b * r_cyl + b**2) / (3 * pi * r_cyl**2)) / inertia,
    "eq. (32)": 2 * G / 3 - q / 2,
    "eq. (32)+(36)": 2 * G / 3 - q / 2 - C * b / (pi * r_cyl),
}
want_P = {
    # P/(M v): the rate at which the model's own equation changes T + V (+ losses), per unit mass
    "eq. (4)": -q + C * (3 * b / (2 * pi * r_cyl) + b**2 / (2 * pi * r_cyl**2)) + b**2 / (4 * pi**2 * r_cyl**2) * (2 * G / 3 - sp.Rational(7, 6) * q),
    "eq. (6)": -sp.Rational(3, 2) * q + C * (3 * b / (2 * pi * r_cyl) + b**2 / (2 * pi * r_cyl**2)) + b**2 / (4 * pi**2 * r_cyl**2) * (2 * G / 3 - sp.Rational(3, 2) * q),
    "eq. (21) printed": -sp.Rational(3, 4) * q,
    "eq. (32)": C * (3 * b / (2 * pi * r_cyl) + b**2 / (2 * pi * r_cyl**2)) + b**2 / (4 * pi**2 * r_cyl**2) * (2 * G / 3 - q / 2),
    "eq. (15)": C * b**2 / (2 * pi * r_cyl**2) + b**2 / (4 * pi**2 * r_cyl**2) * (2 * G / 3 - q / 2 - C * b / (pi * r_cyl)),
}
want_P["eq. (32)+(36)"] = want_P["eq. (15)"]
for name, acc in models.items():
    P = power(acc, False)
    if name in want_P:
        same(f"{name}: P/(M v) = {sp.sstr(want_P[name])[:80]}", P / (M * v), want_P[name])
    else:
        print(f"     {name}: P/(M v) = {sp.factor(sp.simplify(P / (M * v)))}")
# eq. (4) lossless from rest: the energy its equation destroys, in closed form (Loney's u(s), fn. 4)
sv, s0v = sp.symbols("s s0", positive=True)
A4 = 2 * G / (5 * b)
u4 = A4 * sv * (1 - (s0v / sv) ** sp.Rational(10, 3))
r_s = sp.sqrt(sv / pi)
x_s = (sv - s0v) / b
su = sp.symbols("su", positive=True)
int_u = sp.integrate(u4.subs(sv, su), (su, s0v, sv))
int_u_over_s = sp.integrate((u4 / sv).subs(sv, su), (su, s0v, sv))
W4 = rho * l * int_u - rho * l * C * (pi * (r_s**3 - sp.sqrt(s0v / pi) ** 3) + b**2 * x_s / 2) \
    - rho * l * b**2 / (4 * pi) * (2 * G / 3 * x_s - sp.Rational(7, 6) * int_u_over_s)
P4s = (want_P["eq. (4)"] * M).subs(v, sp.sqrt(u4)).subs(x, x_s).subs(r0, sp.sqrt(s0v / pi))  # P/v as a function of s
same("eq. (4) from rest: W_4(s) = rho l int u ds - rho l C (pi (r^3 - r0^3) + b^2 x/2) - (rho l b^2/4pi)(2G x/3 - (7/6) int u/s ds), dW/dx = -P/v",
     sp.diff(W4, sv) * b + P4s, 0)
same("... W_4(s0) = 0", W4.subs(sv, s0v), 0)
same("eq. (32)+(36) = eq. (15): same P", power(models["eq. (32)+(36)"], False), power(models["eq. (15)"], False))
# with losses added to a non-energy model the same way (G -> G - losses/M), P changes only through the b^2 inertia
a4L = sp.solve(sp.Eq(a, 2 * G / 3 - sp.Rational(7, 6) * q - sp.Rational(2, 3) * (Fd + crr * M * N_over_M + Fc) / M), a)[0]
P4L = power(a4L, True)
P4 = power(models["eq. (4)"], False)
# difference = v M_e (a4L - a4) + v (losses) = v (3/2 M)(...) ... check the identity P4L = P4 + v M (r'^2)(a4L - a4)
same("eq. (4) with losses: P = P_lossless + v M r'^2 (a_L - a) (the b^2 inertia term only)",
     P4L - P4 - v * M * rp**2 * (a4L - models["eq. (4)"]), 0)


def ledger_numeric():
    """Turn model (paper coefficients) with drag, rolling resistance and compaction, collision
    `note`: K + V + D_drag + D_rr + D_comp + D_collision - E_created = E0, integrating the turn in
    theta (RK4 on u = theta'^2, d u/d theta = 2 theta''), on random scenarios."""
    print("== turn-model ledger with losses (RK4 in theta), random scenarios")
    rng = random.Random(20261123)
    worst = 0.0
    for case in range(12):
        alpha = math.radians(rng.uniform(10, 50))
        bb, rr0 = rng.uniform(0.002, 0.02), rng.uniform(0.05, 0.3)
        dens, length = rng.uniform(100, 900), rng.uniform(0.5, 2)
        cd, rhoa_, c_rr, e_c = rng.uniform(0, 1.2), 1.2, rng.uniform(0, 0.1), rng.uniform(0, 5)
        collision = rng.choice(["note", "charged"])
        gg = 9.81
        Gs, Cs = gg * math.sin(alpha), gg * math.cos(alpha)
        rl = dens * length
        v0 = rng.uniform(0, 2)
        E0 = 0.75 * math.pi * rl * rr0**2 * v0**2
        V_acc = 0.0  # potential at the start of the current turn
        Dd = Dr = Dc = Dcoll = Ecreated = 0.0
        w0sq = (v0 / rr0) ** 2
        ok = True
        for k in range(6):
            r_ = rr0 + k * bb
            mk = math.pi * rl * r_**2
            c1 = c2 = 2 * bb * r_ / math.pi
            e1 = e2 = e3 = bb / math.pi
            mu = bb / (math.pi * r_)

            def rhs(th, u):
                s_, c_ = math.sin(th), math.cos(th)
                I = 1.5 * r_**2 + c1 * th - c2 * s_
                dI = c1 - c2 * c_
                dW = -Gs * (r_ + e1 * th - e2 * s_) + Cs * (e3 - e2 * c_)
                fd = 0.5 * rhoa_ * cd * 2 * r_ * length * r_**2 * u / mk  # F_d/m_k, v = r theta'
                base = -dW - 0.5 * dI * u - r_ * fd - c_rr * r_ * ((1 + mu * th) * Cs + e2 * u * s_) - e_c * mu
                wdd = base / (I + c_rr * r_ * e2 * (1 - c_))
                n = (1 + mu * th) * Cs + e2 * (wdd * (1 - c_) + u * s_)
                # dissipation per radian (per unit m_k): generalized forces
                return 2 * wdd, r_ * fd, c_rr * r_ * n, e_c * mu

            n_steps = 4000
            h = 2 * math.pi / n_steps
            th, u = 0.0, w0sq
            for _ in range(n_steps):
                k1 = rhs(th, u)
                k2 = rhs(th + h / 2, u + h / 2 * k1[0])
                k3 = rhs(th + h / 2, u + h / 2 * k2[0])
                k4 = rhs(th + h, u + h * k3[0])
                u += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
                Dd += mk * h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
                Dr += mk * h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2])
                Dc += mk * h / 6 * (k1[3] + 2 * k2[3] + 2 * k3[3] + k4[3])
                th += h
                if u <= 0:
                    ok = False
                    break
            if not ok:
                break
            # end of turn: model's own energy
            I_end = 1.5 * r_**2 + c1 * 2 * math.pi
            W_end = -Gs * (r_ * 2 * math.pi + e1 * 2 * math.pi**2) + Cs * e3 * 2 * math.pi
            K_end = mk * I_end * u / 2
            V_end = V_acc + mk * W_end
            total = K_end + V_end + Dd + Dr + Dc + Dcoll - Ecreated
            worst = max(worst, abs(total - E0) / max(E0, mk * Gs * r_))
            # collision
            R_ = r_ + bb
            m_next = math.pi * rl * R_**2
            v_end = r_ * math.sqrt(u)
            v_note = v_end * (R_**2 + 2 * r_**2) / (3 * r_ * R_)
            v2 = v_note**2 - (4 / 3 * Cs * bb if collision == "charged" else 0.0)
            if v2 <= 0:
                break
            K_after = 0.75 * m_next * v2
            jump = m_next * Cs * bb
            if collision == "note":
                Dcoll += K_end - 0.75 * m_next * v_note**2
                Ecreated += jump  # the centre rises by b for free
            else:
                Dcoll += K_end - 0.75 * m_next * v_note**2  # impact loss; the jump is paid from K
            V_acc = V_end + jump
            w0sq = v2 / R_**2
            total = K_after + V_acc + Dd + Dr + Dc + Dcoll - Ecreated
            worst = max(worst, abs(total - E0) / max(E0, mk * Gs * r_))
    check("turn ledger K + V + D_drag + D_rr + D_comp + D_coll - E_created = E0 (RK4, < 1e-9 relative)", worst < 1e-9, f"{worst}")


ledger_numeric()
finish()
