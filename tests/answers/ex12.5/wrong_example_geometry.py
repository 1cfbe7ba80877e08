# expect: L=incorrect, eom=partial, a=partial
# Example 12.5's arrangement copied (cross term +m cos(th) x1' x2'): the wedge's acceleration has the wrong sign.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, g, theta = symbols("m M g theta")
x1, x2 = Function("x1")(t), Function("x2")(t)
v1, v2 = x1.diff(t), x2.diff(t)
L = (M + m) / 2 * v1**2 + m / 2 * v2**2 + m * cos(theta) * v1 * v2 + m * g * x2 * sin(theta)
D = M + m * sin(theta) ** 2
eom = [Eq(x1.diff(t, 2), -m * g * sin(theta) * cos(theta) / D), Eq(x2.diff(t, 2), (M + m) * g * sin(theta) / D)]
a = {"x1": -m * g * sin(theta) * cos(theta) / D, "x2": (M + m) * g * sin(theta) / D}
