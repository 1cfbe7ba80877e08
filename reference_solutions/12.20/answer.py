"""Problem 12.20: polar coordinates about the moving point (v t, a t**2).

x' = r' cos - r sin theta' + v,  y' = r' sin + r cos theta' + 2 a t.
T = m(r'**2 + r**2 theta'**2)/2 + m(v cos + 2 a t sin) r' + m r (2 a t cos - v sin) theta' + m(v**2 + 4 a**2 t**2)/2:
terms of degree 2, 1 and 0 in the velocities -> not homogeneous.
Lagrange = Newton for x'' = y'' = 0 seen from a frame accelerating at (0, 2 a):
r'' - r theta'**2 = -2 a sin(theta),   r theta'' + 2 r' theta' = -2 a cos(theta).
H = T2 - T0 != T, and L depends on t explicitly (dL/dt = 2 m a y' != 0): H is not conserved.
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, v, a = symbols("m v a", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

x = r * cos(theta) + v * t
y = r * sin(theta) + a * t**2
T = m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2

T2 = m * (rd**2 + r**2 * thd**2) / 2
T1 = m * (v * cos(theta) + 2 * a * t * sin(theta)) * rd + m * r * (2 * a * t * cos(theta) - v * sin(theta)) * thd
T0 = m * (v**2 + 4 * a**2 * t**2) / 2
T_split = {"T2": T2, "T1": T1, "T0": T0}
T_homogeneous = False

L = T
eom = [
    Eq(r.diff(t, 2) - r * thd**2, -2 * a * sin(theta)),
    Eq(r * theta.diff(t, 2) + 2 * rd * thd, -2 * a * cos(theta)),
]
H_conserved = False
H_is_E = False
