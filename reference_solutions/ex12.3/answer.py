"""Exercise 12.3: double Atwood machine with massless pulleys."""
from sympy import Eq, Function, symbols

t = symbols("t")
m1, m2, m3, g, l_a, l_b = symbols("m1 m2 m3 g l_a l_b", positive=True)
x1, x2 = Function("x1")(t), Function("x2")(t)
v1, v2 = x1.diff(t), x2.diff(t)

L = m1 / 2 * v1**2 + m2 / 2 * (v2 - v1) ** 2 + m3 / 2 * (v1 + v2) ** 2 \
    + g * (m1 * x1 + m2 * (l_a - x1 + x2) + m3 * (l_a + l_b - x1 - x2))

D = m1 * m2 + m1 * m3 + 4 * m2 * m3
a1 = g * (m1 * m2 + m1 * m3 - 4 * m2 * m3) / D
a2 = 2 * g * m1 * (m2 - m3) / D
eom = [Eq(x1.diff(t, 2), a1), Eq(x2.diff(t, 2), a2)]
a = {"m1": a1, "m2": a2 - a1, "m3": -a1 - a2}
