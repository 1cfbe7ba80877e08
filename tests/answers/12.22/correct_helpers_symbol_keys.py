# Dicts keyed by the mass symbols instead of strings; eom as raw Lagrange expressions; tensions via the harmonic-mean form.
from lagrade.answer import *

m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")

T = m1 / 2 * (dot(x) + dot(y)) ** 2 + m2 / 2 * (dot(x) - dot(y)) ** 2 \
    + m3 / 2 * (dot(z) - dot(x)) ** 2 + m4 / 2 * (dot(x) + dot(z)) ** 2
V = -g * (m1 * (x + y) + m2 * (x + l1 - y) + m3 * (l3 - x + z) + m4 * (l3 - x + l2 - z))
L = T - V
eom = [diff(diff(L, dot(q)), t) - diff(L, q) for q in (x, y, z)]

S = 4 * g * m1 * m2 * m3 * m4 / (m2 * m3 * m4 + m1 * m3 * m4 + m1 * m2 * m4 + m1 * m2 * m3)
a = {mi: g - S / mi for mi in (m1, m2, m3, m4)}
S_t = {Symbol("S1"): S, Symbol("S2"): S, Symbol("S3"): 2 * S}
a_case = {m1: -23 * g / 25, m2: g / 25, m3: 9 * g / 25, m4: 13 * g / 25}
