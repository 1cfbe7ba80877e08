"""Problem 12.3: wall - k - m - k - m on a smooth table."""
from sympy import Eq, Function, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
x1, x2 = Function("x1")(t), Function("x2")(t)

T = m / 2 * (x1.diff(t) ** 2 + x2.diff(t) ** 2)
V = k / 2 * x1**2 + k / 2 * (x2 - x1) ** 2
L = T - V

eom = [
    Eq(m * x1.diff(t, 2), -k * x1 + k * (x2 - x1)),
    Eq(m * x2.diff(t, 2), -k * (x2 - x1)),
]
