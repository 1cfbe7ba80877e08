"""Exercise 12.2: repulsive inverse-square force, polar coordinates.

F_r = +k/r**2 = -dV/dr  ->  V = k/r,  L = m/2 (r'^2 + r^2 theta'^2) - k/r.
r:      m r'' - m r theta'^2 = k/r^2       theta:  d/dt(m r^2 theta') = 0
Q_r = -dV/dr = k/r^2, Q_theta = -dV/dtheta = 0 (no torque).
Constants: p_theta = m r^2 theta' and E = T + V.
Difference: E = T + k/r > 0 always and the effective potential p_theta^2/(2 m r^2) + k/r decreases
monotonically, so there is no minimum: no bound orbits; every orbit is a hyperbola (scattering).
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

L = m / 2 * (rd**2 + r**2 * thd**2) - k / r
eom = [
    Eq(m * r.diff(t, 2) - m * r * thd**2, k / r**2),
    Eq((m * r**2 * thd).diff(t), 0),
]
Q = {"r": k / r**2, "theta": 0}
conserved = [m * r**2 * thd, m / 2 * (rd**2 + r**2 * thd**2) + k / r]
bound_orbits = False
