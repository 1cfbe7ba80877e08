# The solution as A*cos(omega*t + delta) with A and delta from the initial values; H and eqs rearranged.
from sympy import Eq, Function, atan2, cos, sqrt, symbols

t = symbols("t")
m, k, x0, v0 = symbols("m k x0 v0")
x, p_x = Function("x")(t), Function("p_x")(t)
H = (p_x**2 + m * k * x**2) / (2 * m)
hamilton = [Eq(p_x, m * x.diff(t)), Eq(-p_x.diff(t) / k, x)]
w = sqrt(k / m)
A = sqrt(x0**2 + (v0 / w) ** 2)
delta = atan2(-v0 / w, x0)
solution = {"x": A * cos(w * t + delta)}
omega = sqrt(k) / sqrt(m)
