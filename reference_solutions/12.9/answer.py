"""Problem 12.9: particle in spherical coordinates under a force (F_r, F_theta, F_phi).

dr/dr = e_r, dr/dtheta = r e_theta, dr/dphi = r sin(theta) e_phi  ->  Q = (F_r, r F_theta, r sin(theta) F_phi).
(b) phi = phip + omega t: T = m/2 (r'^2 + r^2 theta'^2 + r^2 sin^2(theta) (phip' + omega)^2).
Expanding (phip' + omega)^2 and comparing with (a): omega^2 terms are the generalized centrifugal force, terms linear in omega the
generalized Coriolis force (with d/dt of the omega term in p_phip).
"""
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
# Generalized forces, as the book asks: the extra terms when Lagrange's equations of (b) are written with the
# left-hand side of (a) (phi -> phip); for the angles they are torques, like Q_theta and Q_phi.
centrifugal = {"r": m * omega**2 * r * sin(th) ** 2, "theta": m * omega**2 * r**2 * sin(th) * cos(th), "phip": 0}
coriolis = {"r": 2 * m * omega * r * sin(th) ** 2 * phpd,
            "theta": 2 * m * omega * r**2 * sin(th) * cos(th) * phpd,
            "phip": -2 * m * omega * r * sin(th) * (rd * sin(th) + r * cos(th) * thd)}
eom_b = [
    Eq(m * (rdd - r * thd**2 - r * sin(th) ** 2 * phpd**2), F_r + centrifugal["r"] + coriolis["r"]),
    Eq(m * (r**2 * thdd + 2 * r * rd * thd - r**2 * sin(th) * cos(th) * phpd**2),
       r * F_theta + centrifugal["theta"] + coriolis["theta"]),
    Eq(m * (r**2 * sin(th) ** 2 * phpdd + 2 * r * rd * sin(th) ** 2 * phpd + 2 * r**2 * sin(th) * cos(th) * thd * phpd),
       r * sin(th) * F_phi + coriolis["phip"]),
]
