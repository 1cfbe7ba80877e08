"""Problem 12.48: central attraction (k/r^2) exp(-a t).

V = -k exp(-a t)/r, T = m (r'^2 + r^2 theta'^2)/2, L = T - V.
p_r = m r', p_theta = m r^2 theta', H = p_r^2/(2m) + p_theta^2/(2 m r^2) - k exp(-a t)/r.
r' = p_r/m, theta' = p_theta/(m r^2), p_r' = p_theta^2/(m r^3) - k exp(-a t)/r^2, p_theta' = 0.
dH/dt = partial H/partial t = a k exp(-a t)/r > 0: H is not constant.
The coordinates are fixed (no moving constraint), T is quadratic in the velocities and V does not depend on them,
so H = T + V = E: H is the total energy (and the energy grows as the attraction fades).
"""
from sympy import Eq, Function, exp, symbols

t = symbols("t")
m, k, a = symbols("m k a", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
p_r, p_theta = Function("p_r")(t), Function("p_theta")(t)

L = m * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2) / 2 + k * exp(-a * t) / r
H = p_r**2 / (2 * m) + p_theta**2 / (2 * m * r**2) - k * exp(-a * t) / r
hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(theta.diff(t), p_theta / (m * r**2)),
    Eq(p_r.diff(t), p_theta**2 / (m * r**3) - k * exp(-a * t) / r**2),
    Eq(p_theta.diff(t), 0),
]
H_conserved = False
dH_dt = a * k * exp(-a * t) / r
H_is_E = True
