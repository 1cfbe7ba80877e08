# L built from the block's floor-frame coordinates (X, Y) = (x1 - x2 cos th, -x2 sin th) plus a total
# derivative d/dt(g*x1*x2); the eom scaled by -1 and by m, one written as an expression = 0.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, g, theta = symbols("m M g theta")
x1, x2 = Function("x1")(t), Function("x2")(t)
X = x1 - x2 * cos(theta)
Y = -x2 * sin(theta)
L = M * x1.diff(t) ** 2 / 2 + m * (X.diff(t) ** 2 + Y.diff(t) ** 2) / 2 - m * g * Y + (g * x1 * x2).diff(t)
eom = [Eq(-(M + m) * x1.diff(t, 2), -m * cos(theta) * x2.diff(t, 2)),
       m * x2.diff(t, 2) - m * cos(theta) * x1.diff(t, 2) - m * g * sin(theta)]
D = M + m * sin(theta) ** 2
a = {"x2": (M + m) * g * sin(theta) / D, "x1": m * g * sin(theta) * cos(theta) / D}
