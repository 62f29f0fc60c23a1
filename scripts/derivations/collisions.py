"""The three collision variants at the end of a turn (docs/contact-forces.md §5):
`note` = eq. (89), `charged` = (89) plus the potential energy of the centre's jump,
`pivot` = impact of the corner of the new layer, rotation about it, rolling on r + b.

Run: python3 scripts/derivations/collisions.py   (exits 1 on any FAIL)
"""

import sympy as sp

from _check import check, finish, same, series_zero

r, b, rho, l, G, C, g, al = sp.symbols("r b rho l G C g alpha", positive=True)
w, th = sp.symbols("omega theta", real=True)
rp, tp = sp.symbols("rp tp", positive=True)
pi = sp.pi
R = r + b
rl = rho * l
D = {n: R**n - r**n for n in (2, 3, 4)}

print("== corner of the new layer")
# corner = sector edge t' = theta at r' = r + b, relative to C: (-(r+b) sin theta, r - (r+b) cos theta)
delta = sp.acos(r / R)
thc = 2 * pi - delta
yc = r - R * sp.cos(thc)
same("corner touches y = 0 at theta_c = 2 pi - acos(r/(r+b))", yc, 0)
d = -R * sp.sin(thc)
same("... at d = sqrt(2 r b + b^2) ahead of C", sp.simplify(d), sp.sqrt(2 * r * b + b**2))
# the radial edge and the outer arc lie above the corner: y(r', t') = r - r' cos t' >= y(R, theta_c) for r' <= R, t' <= theta_c near 2 pi
check("the corner is the lowest point of the sector (dy/dr' < 0 and dy/dt' < 0 on the edge near theta_c)",
      sp.simplify(sp.diff(r - rp * sp.cos(tp), rp).subs(tp, thc)) == -r / R and
      sp.simplify(sp.diff(r - R * sp.cos(tp), tp).subs(tp, thc)) == sp.simplify(R * sp.sin(thc)))
eps = sp.symbols("epsilon", positive=True)  # sqrt(b/r)
dl = sp.series(delta.subs(b, eps**2 * r), eps, 0, 5).removeO()
same("delta = sqrt(2b/r) (1 - 5b/(12r)) + O((b/r)^(5/2))", dl, sp.sqrt(2) * eps - sp.Rational(5, 12) * sp.sqrt(2) * eps**3)
ex = sp.series(((d - r * delta) / b).subs(b, eps**2 * r), eps, 0, 2).removeO()
same("d - r delta = (2/3) b sqrt(2b/r) + ...", ex, sp.Rational(2, 3) * sp.sqrt(2) * eps)

print("== impact about E: angular momentum about the impact line")
X = -rp * sp.sin(tp)
Y = r - rp * sp.cos(tp)


def body(f, theta):
    disk = sp.integrate(sp.integrate(f * rp, (tp, 0, 2 * pi)), (rp, 0, r))
    sector = sp.integrate(sp.integrate(f * rp, (tp, 0, theta)), (rp, r, R))
    return sp.simplify(rl * (disk + sector))


dd = sp.symbols("d", positive=True)  # E = (d, 0) relative to C
M = body(1, th)
Sx = body(X, th)
IC = body(X**2 + Y**2, th)
LE_minus = body((X - dd) * X + Y * Y, th)  # omega_z int (X-E).(X-C): rigid rotation about C
IE = body((X - dd) ** 2 + Y**2, th)
same("L_E- = -theta' (I_C - d S_x)", LE_minus, IC - dd * Sx)
same("I_E = I_C - 2 d S_x + M d^2", IE, IC - 2 * dd * Sx + M * dd**2)
# general rigid-body identity used above: L_P = omega_z int (X-P).(X-C) dm for rotation about C
# full ring (theta = 2 pi), E on the rim (|O - E| = R): reproduces eq. (89) exactly
Mfull = pi * rl * R**2
ICfull = Mfull * (R**2 / 2 + r**2)
IEfull = Mfull * (R**2 / 2 + R**2)
same("full ring: I_C = m'(R^2/2 + r^2) [eq. (85)], I_E = 3 m' R^2/2 [eq. (81)]", IC.subs(th, 2 * pi), ICfull)
same("full ring: I_E at d = sqrt(2rb+b^2)", IE.subs(th, 2 * pi).subs(dd, sp.sqrt(2 * r * b + b**2)), IEfull)
ratio_note = (R**2 + 2 * r**2) / (3 * R**2)  # theta'+/theta'- of eq. (89): v'/R over v_end/r
same("eq. (89) = angular momentum about the rim point E of the full ring: theta'+/theta'- = (R^2+2r^2)/(3R^2)",
     ICfull / IEfull, ratio_note)
# exact body at theta_c; for the series, b = eps^2 r and delta, sin, cos of theta_c in closed form
dser = sp.series(sp.acos(1 / (1 + eps**2)), eps, 0, 8).removeO()
subs_c = {sp.sin(th): -d / R, sp.cos(th): r / R}
Mc, Sxc, ICc = [sp.expand(e).subs(subs_c).subs(th, thc) for e in (M, Sx, IC)]
ratio_pivot = (ICc - d * Sxc) / (ICc - 2 * d * Sxc + Mc * d**2)


def eps_series(e, n):
    e = sp.sympify(e).subs(b, eps**2 * r).subs(sp.acos(1 / (1 + eps**2)), dser)
    e = e.subs(sp.acos(r / (r + eps**2 * r)), dser)
    return sp.expand(sp.series(sp.simplify(e), eps, 0, n).removeO())


rp_ser = eps_series(ratio_pivot, 4)
rn_ser = sp.series(ratio_note.subs(b, eps**2 * r), eps, 0, 4).removeO()
same("pivot impact: theta'+/theta'- = 1 - 4b/(3r) + O((b/r)^(3/2)) (= note's to this order)", rp_ser, 1 - sp.Rational(4, 3) * eps**2)
same("note: theta'+/theta'- = 1 - 4b/(3r) + O((b/r)^2)", rn_ser, 1 - sp.Rational(4, 3) * eps**2)
rp5 = eps_series(ratio_pivot, 5)
print(f"     pivot ratio to (b/r)^2: {sp.nsimplify(sp.expand(rp5))}")
print(f"     note  ratio to (b/r)^2: {sp.expand(sp.series(ratio_note.subs(b, eps**2 * r), eps, 0, 5).removeO())}")
# energy after the impact relative to before
Tn = sp.simplify(ratio_note**2 * IEfull / ICfull)
same("note: T+/T- = (R^2 + 2 r^2)/(3 R^2) (errata §1 (79))", Tn, ratio_note)

print("== impulses")
v_end = sp.symbols("v_end", positive=True)
vprime = v_end * (R**2 + 2 * r**2) / (3 * r * R)
same("note: J_x = m'(v' - v_end) = -m' v_end b (r - b)/(3 r R), J_y = 0", Mfull * (vprime - v_end),
     -Mfull * v_end * b * (r - b) / (3 * r * R))
Sy = body(Y, th)
wm = sp.symbols("w_m", positive=True)
Syc = sp.expand(Sy).subs(subs_c).subs(th, thc)
wpl = wm * ratio_pivot
Jx = (wpl - wm) * Syc
Jy = wpl * (Mc * d - Sxc) - wm * (-Sxc)
m0 = pi * rl * r**2
jx_ser = eps_series(Jx / (m0 * wm * r), 3)
jy_ser = eps_series(Jy / (m0 * wm * r), 2)
same("pivot: J_x = -(4/3) m b theta' + ...", jx_ser, -sp.Rational(4, 3) * eps**2)
same("pivot: J_y = m d theta' + ... (d ~ sqrt(2 r b))", jy_ser, sp.sqrt(2) * eps)

print("== pivot phase about the fixed edge E")
psi, M_, rho_e, phid, phidd = sp.symbols("psi M rho_E phidot phiddot", real=True)
# cm - E = rho_E(-sin psi, cos psi); potential M (C y - G x) = M g rho_E cos(psi - alpha)
Vp = M_ * (C * rho_e * sp.cos(psi) - G * (-rho_e * sp.sin(psi)))
same("V(psi) = M g rho_E cos(psi - alpha)", Vp.subs({G: g * sp.sin(al), C: g * sp.cos(al)}), M_ * g * rho_e * sp.cos(psi - al))
# momentum of a rigid body rotating about fixed E (clockwise, psi' = -phi'): p = M phi' rho_E (cos psi, sin psi)
t = sp.symbols("t")
psit = sp.Function("psi")(t)
pvec = [M_ * (-sp.diff(psit, t)) * rho_e * sp.cos(psit), M_ * (-sp.diff(psit, t)) * rho_e * sp.sin(psit)]
pos = [-rho_e * sp.sin(psit), rho_e * sp.cos(psit)]
same("p = M d(r_cm)/dt for the rigid body about fixed E (no accretion)", pvec[0] - M_ * sp.diff(pos[0], t), 0)
subsd = {sp.diff(psit, t, 2): -phidd, sp.diff(psit, t): -phid}
dpx = sp.diff(pvec[0], t).subs(subsd).subs(psit, psi)
dpy = sp.diff(pvec[1], t).subs(subsd).subs(psit, psi)
same("N_E = M [C + rho_E (phi'' sin psi - phi'^2 cos psi)]", dpy + M_ * C, M_ * (C + rho_e * (phidd * sp.sin(psi) - phid**2 * sp.cos(psi))))
same("F_E = M [G - rho_E (phi'' cos psi + phi'^2 sin psi)]", M_ * G - dpx, M_ * (G - rho_e * (phidd * sp.cos(psi) + phid**2 * sp.sin(psi))))
IE_ = sp.symbols("I_E", positive=True)
# EOM about the fixed point: I_E phi'' = -dV/dphi = dV/dpsi
same("I_E phi'' = M g rho_E sin(alpha - psi)", sp.diff(M_ * g * rho_e * sp.cos(psi - al), psi), M_ * g * rho_e * sp.sin(al - psi))
# leading order at the start of the pivot: psi0 ~ delta small, rho_E ~ R, phi'' ~ O(g/R): N_E/M ~ C - R phi'^2
print("     hop at the edge (leading order): R phi'+^2 > g cos(alpha), i.e. v+^2 > g R cos(alpha)")
# barrier: if psi0 > alpha the cm must rise by rho_E (1 - cos(psi0 - alpha)); small angles
p0, A0, sc = sp.symbols("psi0 A0 s", positive=True)
series_zero("barrier M g rho_E (1 - cos(psi0 - alpha)) = M g rho_E (psi0 - alpha)^2/2 + O(4th order)",
            ((1 - sp.cos(p0 - al)) - (p0 - al) ** 2 / 2).subs({p0: sc * p0, al: sc * A0}), sc, 4)

print("== charged")
vn, vc = sp.symbols("v_note v_c", positive=True)
mp = sp.symbols("m_next", positive=True)
sol = sp.solve(sp.Eq(sp.Rational(3, 4) * mp * vc**2, sp.Rational(3, 4) * mp * vn**2 - mp * C * b), vc)
same("charged: v'^2 = v_note'^2 - (4/3) g b cos(alpha)", sol[0] ** 2, vn**2 - sp.Rational(4, 3) * C * b)
same("charged v'^2 exact in v_end", (vprime**2 - sp.Rational(4, 3) * C * b),
     v_end**2 * ((R**2 + 2 * r**2) / (3 * r * R)) ** 2 - sp.Rational(4, 3) * C * b)

print("== pivot energy bookkeeping to leading order (cm at the centre O)")
# the centre moves from (0, r) to (d, R) about E: Delta V = M (C b - G d)
same("pivot: Delta V_pivot = M (C b - G d) when cm = O", M_ * (C * (R - r) - G * d), M_ * (C * b - G * sp.sqrt(2 * r * b + b**2)))

finish()
