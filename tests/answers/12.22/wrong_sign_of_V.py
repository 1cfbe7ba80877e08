# expect: L=incorrect, eom=incorrect, a=correct, S_t=correct, a_case=correct
# With depths measured downward V must be -g*sum(m_i*depth_i); the student used +g*sum(...) (and the eom follow it).
from lagrade.answer import *

m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")
T = m1 / 2 * (dot(x) + dot(y)) ** 2 + m2 / 2 * (dot(x) - dot(y)) ** 2 \
    + m3 / 2 * (dot(z) - dot(x)) ** 2 + m4 / 2 * (dot(x) + dot(z)) ** 2
V = g * (m1 * (x + y) + m2 * (x + l1 - y) + m3 * (l3 - x + z) + m4 * (l3 - x + l2 - z))
L = T - V
eom = [diff(diff(L, dot(q)), t) - diff(L, q) for q in (x, y, z)]
S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)
a = {"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3, "m4": g - S / m4}
S_t = {"S1": S, "S2": S, "S3": 2 * S}
a_case = {"m1": -Rational(23, 25) * g, "m2": g / 25, "m3": Rational(9, 25) * g, "m4": Rational(13, 25) * g}
