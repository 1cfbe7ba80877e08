# Accelerations from the tensions (S on the lower string, 2S on the upper one); eom scaled and added.
from sympy import Eq, Function, symbols

t = symbols("t")
m1, m2, m3, g, l_a, l_b = symbols("m1 m2 m3 g l_a l_b", positive=True)
x1, x2 = Function("x1")(t), Function("x2")(t)
v1, v2 = x1.diff(t), x2.diff(t)
L = m1 / 2 * v1**2 + m2 / 2 * (v2 - v1) ** 2 + m3 / 2 * (v1 + v2) ** 2 \
    + g * (m1 * x1 + m2 * (l_a - x1 + x2) + m3 * (l_a + l_b - x1 - x2))
A1, A2 = x1.diff(t, 2), x2.diff(t, 2)
E1 = Eq(m1 * A1 - m2 * (A2 - A1) + m3 * (A1 + A2), g * (m1 - m2 - m3))
E2 = Eq(m2 * (A2 - A1) + m3 * (A1 + A2), g * (m2 - m3))
eom = [Eq(E1.lhs + E2.lhs, E1.rhs + E2.rhs), Eq(3 * E2.lhs, 3 * E2.rhs)]
# a_i (down) = g - S_i/m_i with S_1 = 2S; string: a2 + a3 = -2 a1
S = 4 * g / (4 / m1 + 1 / m2 + 1 / m3)
a = {"m1": g - 2 * S / m1, "m2": g - S / m2, "m3": g - S / m3}
