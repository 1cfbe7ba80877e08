"""Problem 12.8: point mass on a free wedge. (a) plane face at angle theta, (b) convex quarter-circle face.

(a) m at (x1 + x2 cos a, -x2 sin a): v^2 = x1'^2 + 2 cos(a) x1' x2' + x2'^2.
(b) m at (X + R sin th, R cos th): v^2 = X'^2 + 2 R cos(th) X' th' + R^2 th'^2.
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, g, R = symbols("m M g R", positive=True)
alpha = symbols("theta", positive=True)  # (a): the incline angle, named theta like the catalogue
x1, x2 = Function("x1")(t), Function("x2")(t)
X, th = Function("X")(t), Function("theta")(t)

# (a)
u1, u2 = x1.diff(t), x2.diff(t)
L_a = M * u1**2 / 2 + m * (u1**2 + 2 * cos(alpha) * u1 * u2 + u2**2) / 2 + m * g * x2 * sin(alpha)
D = M + m * sin(alpha) ** 2
eom_a = [
    Eq(x1.diff(t, 2), -m * g * sin(alpha) * cos(alpha) / D),
    Eq(x2.diff(t, 2), (M + m) * g * sin(alpha) / D),
]

# (b)
U, w = X.diff(t), th.diff(t)
L_b = M * U**2 / 2 + m * (U**2 + 2 * R * cos(th) * U * w + R**2 * w**2) / 2 - m * g * R * cos(th)
eom_b = [
    Eq((M + m) * X.diff(t, 2) + m * R * (cos(th) * th.diff(t, 2) - sin(th) * w**2), 0),   # p_X conserved
    Eq(R * th.diff(t, 2) + cos(th) * X.diff(t, 2), g * sin(th)),
]
