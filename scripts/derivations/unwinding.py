"""The unwinding roll (issue 35, docs/unwinding.md): b < 0 in pi r^2 = pi r0^2 + b x (eq. (8)).

Checks, with sympy, each closed form that crates/snowroll/tests/unwinding.rs types:

1. the textbook energy balance of an unrolling roll on a level floor (body only, the laid layer at
   rest at zero height, its thickness and r'^2 neglected) gives v^2 = 4g(R^3 - r^3)/(3 r^2), and it
   solves eq. (15) with b < 0 (and v^2 = 14 g R/3 at r = R/2); the ball's version
   v^2 = (10g/7)(R^4 - r^4)/r^3 solves the ball's linearised energy balance;
2. eq. (11) differentiated along the motion is eq. (14) for any sign of b;
3. fn. 4's form u = v0^2 (s0/s)^n + 2 P G/((n+1) b) (s - s0 (s0/s)^n) solves a = P G - c_v b v^2/s
   (eqs. (4), (6), (32)) for any b;
4. the integral of eq. (21) on a level floor solves it;
5. who starts from rest on a level floor: a(v = 0, alpha = 0) of each model;
6. which geometry eq. (10) with b < 0 describes: the laid layer's centre of mass at +|b|/2 above
   the plane the roll's centre is r above (the b^2 term of the potential), against a roll that rides
   on its own laid layer, whose term has the other sign;
7. the tube (docs/unwinding.md, "The core"): each balance written with M(x) and I(x), divided by M,
   is the one form of that section (j = I/(M r^2), j' = I'/(M r^2), lambda = M'/M); with
   I = k M r^2, M ~ r^n it is the uniform body's form of docs/snowball-and-losses.md section 1.2;
   and on a level floor v^2 = 2g (M(R) R - M(r) r)/(M(r) + I(r)/r^2) solves eq. (15) with the tube
   (the closed form crates/snowroll/tests/unwinding_core.rs types).
"""

import sympy as sp

from _check import check, finish, same

g, R, r, x, b, v0, G, C, rho, l, s, s0, sig = sp.symbols(
    "g R r x b v0 G C rho l s s0 sigma", real=True
)
pi = sp.pi


def u_of_s_ode(u, acc, k=0):
    """The residual of (1 + k/s) (b/2) du/ds = acc(u, s) for u(s), r = sqrt(s/pi)."""
    return sp.simplify((1 + k / s) * b / 2 * sp.diff(u, s) - acc(u, s))


# 1. The textbook balance and eq. (15).
M = lambda rr: rho * l * pi * rr**2  # noqa: E731
E_start = M(R) * g * R
v2_text = sp.solve(sp.Eq(E_start, M(r) * g * r + sp.Rational(3, 4) * M(r) * sp.Symbol("w2")), sp.Symbol("w2"))[0]
same("textbook: v^2 = 4g(R^3 - r^3)/(3 r^2)", v2_text, 4 * g * (R**3 - r**3) / (3 * r**2))
same("textbook: v^2 = 14 g R/3 at r = R/2", v2_text.subs(r, R / 2), 14 * g * R / 3)
u15 = (4 * g * (R**3 - (s / pi) ** sp.Rational(3, 2)) / (3 * s / pi))
acc15 = lambda u, ss: -b * u / (2 * ss) - g * b / (pi * sp.sqrt(ss / pi))  # noqa: E731  eq. (15), alpha = 0
check("eq. (15), b of either sign, alpha = 0: solved by the textbook u(s)", sp.simplify(u_of_s_ode(u15, acc15)) == 0)
# The ball: M ∝ r^3, k = 2/5; linearised energy: M0 g R = M g r + (7/10) M v^2.
Mb = lambda rr: rho * sp.Rational(4, 3) * pi * rr**3  # noqa: E731
v2_ball = sp.solve(sp.Eq(Mb(R) * g * R, Mb(r) * g * r + sp.Rational(7, 10) * Mb(r) * sp.Symbol("w2")), sp.Symbol("w2"))[0]
same("ball textbook: v^2 = (10g/7)(R^4 - r^4)/r^3", v2_ball, sp.Rational(10, 7) * g * (R**4 - r**4) / r**3)
# Its equation of motion from d/dx of the energy, with dr/dx = b/(2 pi r) (the natural swath 2r):
# d/dx[M g r + (7/10) M v^2] = 0 with M' = 3 M r'/r, r' = b/(2 pi r):
rr = sp.Function("rr")(x)
vv = sp.Function("vv")(x)
energy_b = Mb(rr) * g * rr + sp.Rational(7, 10) * Mb(rr) * vv**2
d = sp.diff(energy_b, x).subs(sp.Derivative(rr, x), b / (2 * pi * rr))
a_ball = sp.solve(d, sp.Derivative(vv, x))[0] * vv  # a = v dv/dx
a_ball = sp.simplify(a_ball.subs({vv: sp.sqrt(sp.Symbol("u")), rr: r}))
uu = sp.Symbol("u")
# Check the textbook u(r) of the ball against this a = (1/2) du/dx, du/dx = (du/dr)(b/(2 pi r)).
u_ball_r = sp.Rational(10, 7) * g * (R**4 - r**4) / r**3
lhs = sp.Rational(1, 2) * sp.diff(u_ball_r, r) * b / (2 * pi * r)
check("ball: (1/2) du/dx of the textbook u is the energy balance's a", sp.simplify(lhs - a_ball.subs(uu, u_ball_r)) == 0)

# 2. Eq. (11) -> eq. (14), b of either sign (x = (s - s0)/b, r = sqrt(s/pi)).
t = sp.Symbol("t")
X = sp.Function("X")(t)
r0 = sp.Symbol("r0", positive=True)
rt = sp.sqrt(r0**2 + b * X / pi)
alpha = sp.Symbol("alpha", real=True)
V = sp.Derivative(X, t)
E11 = (
    3 * pi * rt**2 * V**2 / 4
    + b**2 * V**2 / (8 * pi)
    + g * ((2 * pi * rt**3 + b**2 * X) * sp.cos(alpha) + (b * X**2 - 2 * pi * rt**2 * X) * sp.sin(alpha)) / 2
    - pi * r0**3 * g * sp.cos(alpha)
)
dE = sp.diff(E11, t)
A = sp.Symbol("A")
dE = dE.subs(sp.Derivative(X, (t, 2)), A)
a11 = sp.solve(dE, A)[0]
rr_ = sp.Symbol("r", positive=True)
vv_ = sp.Symbol("v", real=True)
a14 = (
    2 * g * sp.sin(alpha) / 3 - b * vv_**2 / (2 * pi * rr_**2) - g * sp.cos(alpha) * (3 * b * rr_ + b**2) / (3 * pi * rr_**2)
) / (1 + b**2 / (6 * pi**2 * rr_**2))
a11 = a11.subs(sp.Derivative(X, t), vv_).subs(X, pi * (rr_**2 - r0**2) / b)
check("eq. (11) differentiated is eq. (14) for any sign of b", sp.simplify(a11 - a14) == 0)

# 3. fn. 4's form for eqs. (4), (6), (32): a = P G - c_v b u/s.
n, P = sp.symbols("n P", positive=True)
u_fn4 = v0**2 * (s0 / s) ** n + 2 * P * G / ((n + 1) * b) * (s - s0 * (s0 / s) ** n)
acc_drag = lambda u, ss: P * G - (n / 2) * b * u / ss  # noqa: E731  c_v = n/2
check("fn. 4's form solves a = P G - c_v b v^2/(pi r^2) for any b", sp.simplify(u_of_s_ode(u_fn4, acc_drag)) == 0)
check("fn. 4's form starts at v0", sp.simplify(u_fn4.subs(s, s0) - v0**2) == 0)

# 4. Eq. (21) on a level floor: (s + k) u' = -2u - 2g r - 2g b/3, k = b^2/(6 pi).
k = b**2 / (6 * pi)
F1 = lambda q: sp.Rational(2, 5) * q ** sp.Rational(5, 2) + 2 * k / 3 * q ** sp.Rational(3, 2)  # noqa: E731
F2 = lambda q: q**2 / 2 + k * q  # noqa: E731
u21 = -(2 * g / sp.sqrt(pi) * (F1(s) - F1(s0)) + 2 * g * b / 3 * (F2(s) - F2(s0))) / (s + k) ** 2
acc21 = lambda u, ss: -b * u / ss - g * (3 * sp.sqrt(ss / pi) * b + b**2) / (3 * ss)  # noqa: E731
check("the integral of eq. (21), alpha = 0, solves it", sp.simplify(u_of_s_ode(u21, acc21, k)) == 0)
check("the integral of eq. (21) starts from rest", sp.simplify(u21.subs(s, s0)) == 0)

# 5. From rest on a level floor (alpha = 0, v = 0), b < 0, 0 < r: a of each equation.
bn = sp.Symbol("beta", positive=True)  # b = -beta
rp = sp.Symbol("r", positive=True)
a_rest = {
    "eq. (4) torque-cm": sp.Integer(0),
    "eq. (6) torque-contact": sp.Integer(0),
    "eq. (32) quasi-circular": sp.Integer(0),
    "eq. (15) energy-thin": -g * (-bn) / (pi * rp),
    "eq. (14) energy": -g * (3 * (-bn) * rp + bn**2) / (3 * pi * rp**2) / (1 + bn**2 / (6 * pi**2 * rp**2)),
}
for name, a in a_rest.items():
    if a == 0:
        check(f"{name}: a = 0 at rest on a level floor (does not start)", True)
    else:
        # Positive while |b| < 3r: the layer is thinner than the roll.
        check(f"{name}: a > 0 at rest on a level floor for |b| < 3r", sp.simplify(a.subs({bn: rp / 10, g: 1})) > 0)

# 6. Eq. (10) with b < 0: the b^2 term. The laid layer (mass -rho b l x) with its centre of mass at
# height h (normal to the slope): potential -rho b l x g h cos(alpha). Eq. (10)'s term
# rho b l x g b cos(alpha)/2 is this with h = -b/2 = +|b|/2; a roll riding on its laid layer has it
# at h = -|b|/2 = b/2 below the plane its centre is r above, which flips the term's sign.
h = sp.Symbol("h", real=True)
layer = -rho * b * l * x * g * h * sp.cos(alpha)
same("eq. (10)'s layer term is the laid layer at h = -b/2 (+|b|/2 for b < 0)",
     layer.subs(h, -b / 2), rho * b * l * x * g * b * sp.cos(alpha) / 2)
same("a roll riding on its layer (h = b/2): the b^2 term's sign flips",
     layer.subs(h, b / 2), -rho * b * l * x * g * b * sp.cos(alpha) / 2)

# 7. The tube. Each balance with general M(X), I(X), r(X) along the distance X, speed V, a = dV/dt:
# d/dt f(X, V) = V df/dX + a df/dV.
X, V, a_, Gs, Cs = sp.symbols("X V a G C", real=True)
Mf, If, rf = sp.Function("M")(X), sp.Function("I")(X), sp.Function("r")(X)


def ddt(expr):
    return sp.diff(expr, X) * V + sp.diff(expr, V) * a_


r1, r2 = sp.diff(rf, X), sp.diff(rf, X, 2)
U1 = lambda lb: sp.diff(Mf, X) * Cs * (rf + lb * b / 2) + Mf * Cs * r1 - Mf * Gs  # noqa: E731  dU/dX
A_full = Mf * (1 + r1**2) + If / rf**2
A_thin = Mf + If / rf**2
balances = {
    # name: (residual = 0, (eps, c_n, c_1, c_k, c_rr, lift, lift_b))
    "eqs. (2)-(3), torque about the centre": (
        ddt(Mf * V) + ddt(If * V / rf) / rf - Mf * Gs, (0, 1, 0, 1, 0, 0, 0)),
    "eq. (5), torque about the contact line": (
        ddt((If + Mf * rf**2) * V / rf) - Mf * Gs * rf, (0, 1, 1, 0, 0, 0, 0)),
    "eq. (14), energy with r'^2 and the layer's b/2": (
        ddt(A_full * V**2 / 2) + V * U1(1), (1, sp.Rational(1, 2), 0, 0, 1, 1, 1)),
    "eq. (15), energy to first order": (
        ddt(A_thin * V**2 / 2) + V * U1(0), (0, sp.Rational(1, 2), 0, 0, 0, 1, 0)),
    "eq. (21) as printed, without dT/dx": (
        ddt(A_full * V) + U1(1), (1, 1, 0, 0, 2, 1, 1)),
    "eq. (32)": (
        A_thin * a_ + sp.diff(A_thin, X) * V**2 / 2 - Mf * Gs, (0, sp.Rational(1, 2), 0, 0, 0, 0, 0)),
}
j = If / (Mf * rf**2)
jp = sp.diff(If, X) / (Mf * rf**2)
lam = sp.diff(Mf, X) / Mf


def one_form(eps, c_n, c_1, c_k, c_rr, lift, lift_b):
    v2 = (c_n * (lam * (1 + eps * r1**2) + jp - 2 * j * r1 / rf) + eps * c_rr * r1 * r2
          + (c_1 + c_k) * j * r1 / rf + c_1 * r1 / rf)
    lift_terms = Cs * (lift * (lam * rf + r1) + lift_b * lam * b / 2)
    return (Gs - v2 * V**2 - lift_terms) / (1 + j + eps * r1**2)


k_, n_ = sp.symbols("k n", positive=True)
rr_ = sp.Function("rho_r")(X)
for name, (residual, consts) in balances.items():
    a_sol = sp.solve(sp.expand(residual), a_)[0]
    check(f"tube: {name} is the one form of 'The core'", sp.simplify(a_sol - one_form(*consts)) == 0)
    # A uniform body: I = k M r^2, M = c r^n: the form of docs/snowball-and-losses.md section 1.2.
    cm = sp.Symbol("c_m", positive=True)
    uni = {If: k_ * cm * rf**(n_ + 2), Mf: cm * rf**n_}
    eps, c_n, c_1, c_k, c_rr, lift, lift_b = consts
    lam_u = n_ * r1 / rf
    inertia = 1 + k_ + eps * r1**2
    sec12 = (Gs - (c_n * lam_u * inertia + (c_1 * (1 + k_) + c_k * k_) * r1 / rf + eps * c_rr * r1 * r2) * V**2
             - Cs * (lift * (lam_u * rf + r1) + lift_b * lam_u * b / 2)) / inertia
    got = one_form(*consts).subs(uni).doit()
    check(f"tube: {name}, uniform body: the form of section 1.2", sp.simplify(got - sec12) == 0)

# The closed form on a level floor: u(r) = 2g (M(R) R - M(r) r)/(M + I/r^2) with the log's tube
# solves eq. (15)'s one form, a = (1/2) du/dx, du/dx = (du/dr) b/(2 pi r), G = 0, C = g.
mc, rc = sp.symbols("m_c r_c", positive=True)
M_t = mc + rho * l * pi * (r**2 - rc**2)
I_t = mc * rc**2 + rho * l * pi * (r**4 - rc**4) / 2
u_t = 2 * g * (M_t.subs(r, R) * R - M_t * r) / (M_t + I_t / r**2)
dr_dx = b / (2 * pi * r)
lam_t = sp.diff(M_t, r) * dr_dx / M_t
j_t = I_t / (M_t * r**2)
jp_t = sp.diff(I_t, r) * dr_dx / (M_t * r**2)
a15 = (-(sp.Rational(1, 2) * (lam_t + jp_t - 2 * j_t * dr_dx / r)) * u_t
       - g * (lam_t * r + dr_dx)) / (1 + j_t)
check("tube, level floor: u = 2g (M(R) R - M r)/(M + I/r^2) solves eq. (15)",
      sp.simplify(sp.diff(u_t, r) * dr_dx / 2 - a15) == 0)

finish()
