# expect: L=incorrect, eom=incorrect, a=incorrect
# Velocities added as if perpendicular (no cross term): the wedge never moves and the block slides as on a fixed incline.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, g, theta = symbols("m M g theta")
x1, x2 = Function("x1")(t), Function("x2")(t)
v1, v2 = x1.diff(t), x2.diff(t)
L = (M + m) / 2 * v1**2 + m / 2 * v2**2 + m * g * x2 * sin(theta)
eom = [Eq(x1.diff(t, 2), 0), Eq(x2.diff(t, 2), g * sin(theta))]
a = {"x1": 0, "x2": g * sin(theta)}
