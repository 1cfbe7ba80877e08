"""Exercise 12.5: block on a free wedge, mirror image of Example 12.5.

Sliding down the incline carries the block in -x1, so its velocity is x1' i + x2' (-cos th, -sin th):
v^2 = x1'^2 + x2'^2 - 2 x1' x2' cos(th); height drops by x2 sin(th).
x1: d/dt[(M + m) x1' - m cos(th) x2'] = 0
x2: m x2'' - m cos(th) x1'' = m g sin(th)
=> x2'' = (M + m) g sin(th) / (M + m sin^2 th),  x1'' = m g sin(th) cos(th) / (M + m sin^2 th) > 0:
the same magnitudes as in the example; the wedge now recoils in +x1.
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, g, theta = symbols("m M g theta", positive=True)
x1, x2 = Function("x1")(t), Function("x2")(t)
v1, v2 = x1.diff(t), x2.diff(t)

L = M / 2 * v1**2 + m / 2 * (v1**2 + v2**2 - 2 * v1 * v2 * cos(theta)) + m * g * x2 * sin(theta)
eom = [
    Eq((M + m) * x1.diff(t, 2) - m * cos(theta) * x2.diff(t, 2), 0),
    Eq(x2.diff(t, 2) - cos(theta) * x1.diff(t, 2), g * sin(theta)),
]
D = M + m * sin(theta) ** 2
a = {"x1": m * g * sin(theta) * cos(theta) / D, "x2": (M + m) * g * sin(theta) / D}
