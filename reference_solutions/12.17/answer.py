"""Problem 12.17: m1 on a smooth table, cord of length l through a hole, m2 a planar pendulum below.

m1 at (r, phi) on the table; m2 at distance s = l - r below the hole, at angle theta:
v2**2 = s'**2 + s**2 theta'**2 = r'**2 + (l - r)**2 theta'**2, height -(l - r) cos(theta).
"""
from sympy import Eq, Function, cos, diff, sin, sqrt, symbols

t = symbols("t")
m1, m2, l, g, r0, J = symbols("m1 m2 l g r0 J", positive=True)
r, phi, theta = Function("r")(t), Function("phi")(t), Function("theta")(t)
rd, phid, thd = r.diff(t), phi.diff(t), theta.diff(t)

T = m1 / 2 * (rd**2 + r**2 * phid**2) + m2 / 2 * (rd**2 + (l - r) ** 2 * thd**2)
V = -m2 * g * (l - r) * cos(theta)
L = T - V

eom = [
    Eq((m1 + m2) * r.diff(t, 2), m1 * r * phid**2 - m2 * (l - r) * thd**2 - m2 * g * cos(theta)),
    Eq(diff(m1 * r**2 * phid, t), 0),
    Eq((l - r) * theta.diff(t, 2) - 2 * rd * thd + g * sin(theta), 0),
]

a = {
    "r": (m1 * r * phid**2 - m2 * (l - r) * thd**2 - m2 * g * cos(theta)) / (m1 + m2),
    "phi": -2 * rd * phid / r,
    "theta": (2 * rd * thd - g * sin(theta)) / (l - r),
}

# m1 along the cord: m1 (r'' - r phi'**2) = -S
S_t = m1 * (r * phid**2 - a["r"])

# phi is cyclic: p_phi = m1 r**2 phi' = J; no explicit t: the energy is conserved
conserved = [m1 * r**2 * phid, T + V]

# theta = 0: (m1 + m2) r'' = J**2/(m1 r**3) - m2 g; steady at r0 when J**2 = m1 m2 g r0**3.
x = symbols("x", positive=True)
F = J**2 / (m1 * x**3) - m2 * g
k = -diff(F, x).subs(x, r0).subs(J, sqrt(m1 * m2 * g * r0**3))
omega_r = sqrt(k / (m1 + m2))                      # = sqrt(3 m2 g/((m1 + m2) r0))
# theta equation at r = r0, r' = 0, small theta: (l - r0) theta'' + g theta = 0
omega_p = sqrt(g / (l - r0))
omega = [omega_r, omega_p]
