"""Problem 12.22: the compound Atwood machine.

Tension: every mass feels S - m_i g (up), so a_i(down) = g - S/m_i; with S1 on A, S2 on B and
S3 = 2 S1 = 2 S2 (massless pulleys), the string constraints give S1 = S2 = 4 g / (1/m1 + 1/m2 + 1/m3 + 1/m4).
"""
from sympy import Eq, Function, Rational, symbols

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

T = m1 / 2 * (xd + yd) ** 2 + m2 / 2 * (xd - yd) ** 2 + m3 / 2 * (zd - xd) ** 2 + m4 / 2 * (xd + zd) ** 2
V = -g * (m1 * (x + y) + m2 * (x + l1 - y) + m3 * (l3 - x + z) + m4 * (l3 - x + l2 - z))
L = T - V

D = m1 * m2 * m3 + m1 * m2 * m4 + m1 * m3 * m4 + m2 * m3 * m4
xdd = g * (m1 * m2 * m3 + m1 * m2 * m4 - m1 * m3 * m4 - m2 * m3 * m4) / D
ydd = 2 * g * m3 * m4 * (m1 - m2) / D
zdd = 2 * g * m1 * m2 * (m3 - m4) / D
eom = [Eq(x.diff(t, 2), xdd), Eq(y.diff(t, 2), ydd), Eq(z.diff(t, 2), zdd)]

S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)
a = {"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3, "m4": g - S / m4}
S_t = {"S1": S, "S2": S, "S3": 2 * S}

a_case = {"m1": -Rational(23, 25) * g, "m2": g / 25, "m3": Rational(9, 25) * g, "m4": Rational(13, 25) * g}
