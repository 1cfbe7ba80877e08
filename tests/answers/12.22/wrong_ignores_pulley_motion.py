# expect: L=incorrect, eom=correct, a=correct, S_t=correct, a_case=correct
# The masses' velocities omit the motion of their pulleys (m1's velocity taken as y' instead of x' + y').
from lagrade.answer import *

m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")
L = (m1 + m2) / 2 * dot(y) ** 2 + (m3 + m4) / 2 * dot(z) ** 2 \
    + g * (m1 * (x + y) + m2 * (x + l1 - y) + m3 * (l3 - x + z) + m4 * (l3 - x + l2 - z))
D = m1 * m2 * m3 + m1 * m2 * m4 + m1 * m3 * m4 + m2 * m3 * m4
eom = [Eq(dot(x, 2), g * (m1 * m2 * m3 + m1 * m2 * m4 - m1 * m3 * m4 - m2 * m3 * m4) / D),
       Eq(dot(y, 2), 2 * g * m3 * m4 * (m1 - m2) / D), Eq(dot(z, 2), 2 * g * m1 * m2 * (m3 - m4) / D)]
S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)
a = {"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3, "m4": g - S / m4}
S_t = {"S1": S, "S2": S, "S3": 2 * S}
a_case = {"m1": -Rational(23, 25) * g, "m2": g / 25, "m3": Rational(9, 25) * g, "m4": Rational(13, 25) * g}
