# expect: L=incorrect, eom=correct, a=correct
# Kinetic energy ignores the motion of the movable pulley: m2 and m3 are given speed x2' only.
from lagrade.answer import *

m1, m2, m3, g, l_a, l_b = parameters("m1 m2 m3 g l_a l_b")
x1, x2 = coordinates("x1 x2")
L = m1 / 2 * dot(x1) ** 2 + (m2 + m3) / 2 * dot(x2) ** 2 \
    + g * (m1 * x1 + m2 * (l_a - x1 + x2) + m3 * (l_a + l_b - x1 - x2))
D = m1 * m2 + m1 * m3 + 4 * m2 * m3
a1 = g * (m1 * m2 + m1 * m3 - 4 * m2 * m3) / D
a2 = 2 * g * m1 * (m2 - m3) / D
eom = [Eq(dot(x1, 2), a1), Eq(dot(x2, 2), a2)]
a = {"m1": a1, "m2": a2 - a1, "m3": -a1 - a2}
