# expect: L=correct, eom=incorrect, a=incorrect
# Right Lagrangian, but the 2x2 system solved with the printed example's slip: denominator M + m - m*cos(theta)
# instead of M + m - m*cos(theta)**2.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, g, theta = symbols("m M g theta")
x1, x2 = Function("x1")(t), Function("x2")(t)
v1, v2 = x1.diff(t), x2.diff(t)
L = M / 2 * v1**2 + m / 2 * (v1**2 + v2**2 - 2 * v1 * v2 * cos(theta)) + m * g * x2 * sin(theta)
D = M + m - m * cos(theta)
eom = [Eq(x1.diff(t, 2), m * g * sin(theta) * cos(theta) / D), Eq(x2.diff(t, 2), (M + m) * g * sin(theta) / D)]
a = {"x1": m * g * sin(theta) * cos(theta) / D, "x2": (M + m) * g * sin(theta) / D}
