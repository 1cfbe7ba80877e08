# expect: eom_a=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, omega, F_r, F_theta, F_phi = symbols("m omega F_r F_theta F_phi")
r, th, ph = Function("r")(t), Function("theta")(t), Function("phi")(t)
php = Function("phip")(t)
rd, thd, phd, phpd = r.diff(t), th.diff(t), ph.diff(t), php.diff(t)
rdd, thdd, phdd, phpdd = r.diff(t, 2), th.diff(t, 2), ph.diff(t, 2), php.diff(t, 2)

L_a = m * (rd**2 + r**2 * thd**2 + r**2 * sin(th) ** 2 * phd**2) / 2
Q_a = {"r": F_r, "theta": r * F_theta, "phi": r * sin(th) * F_phi}
eom_a = [
    Eq(m * (rdd - r * thd**2 - r * sin(th) ** 2 * phd**2), F_r),
    Eq(m * (r * thdd + 2 * rd * thd - r * sin(th) * cos(th) * phd**2), F_theta),
    Eq(m * (r * sin(th) * phdd + 2 * rd * sin(th) * phd + 2 * r * cos(th) * thd * phd), F_phi),
]

L_b = m * (rd**2 + r**2 * thd**2 + r**2 * sin(th) ** 2 * (phpd + omega) ** 2) / 2
centrifugal = {"r": m * omega**2 * r * sin(th) ** 2, "theta": m * omega**2 * r**2 * sin(th) * cos(th), "phip": 0}
coriolis = {"r": 2 * m * omega * r * sin(th) ** 2 * phpd,
            "theta": 2 * m * omega * r**2 * sin(th) * cos(th) * phpd,
            "phip": -2 * m * omega * r * sin(th) * (rd * sin(th) + r * cos(th) * thd)}
eom_b = [
    Eq(m * (rdd - r * thd**2 - r * sin(th) ** 2 * phpd**2), F_r + centrifugal["r"] + coriolis["r"]),
    Eq(m * (r * thdd + 2 * rd * thd - r * sin(th) * cos(th) * phpd**2), F_theta + (centrifugal["theta"] + coriolis["theta"]) / r),
    Eq(m * (r * sin(th) * phpdd + 2 * rd * sin(th) * phpd + 2 * r * cos(th) * thd * phpd), F_phi + coriolis["phip"] / (r * sin(th))),
]

# ---- the form under test
# Lagrange's equations with the generalized forces left as the symbols Q_r, Q_theta, Q_phi (issue 22).
from sympy import Eq, Function, sin, symbols

t = symbols("t")
m, Q_r, Q_theta, Q_phi = symbols("m Q_r Q_theta Q_phi")
r, th, ph = Function("r")(t), Function("theta")(t), Function("phi")(t)
L = m * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2 + r**2 * sin(th) ** 2 * ph.diff(t) ** 2) / 2
eom_a = [Eq(L.diff(q.diff(t)).diff(t) - L.diff(q), Q) for q, Q in ((r, Q_r), (th, Q_theta), (ph, Q_phi))]
