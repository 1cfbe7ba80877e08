# expect: a=incorrect, L=correct, eom=correct
# Tension method with the same tension S in both strings; the massless movable pulley needs 2S above it.
from lagrade.answer import *

m1, m2, m3, g, l_a, l_b = parameters("m1 m2 m3 g l_a l_b")
x1, x2 = coordinates("x1 x2")
L = m1 / 2 * dot(x1) ** 2 + m2 / 2 * (dot(x2) - dot(x1)) ** 2 + m3 / 2 * (dot(x1) + dot(x2)) ** 2 \
    + g * (m1 * x1 + m2 * (l_a - x1 + x2) + m3 * (l_a + l_b - x1 - x2))
eom = [diff(diff(L, dot(q)), t) - diff(L, q) for q in (x1, x2)]
# a2 + a3 = -2 a1 with a1 = g - S/m1:  4g = S (2/m1 + 1/m2 + 1/m3)
S = 4 * g / (2 / m1 + 1 / m2 + 1 / m3)
a = {"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3}
