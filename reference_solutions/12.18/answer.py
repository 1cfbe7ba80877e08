"""Problem 12.18: m1 moves along a line on the table, m2 straight up and down below the hole.

Both move with speed |r'|: T = (m1 + m2) r'**2/2; m2 is at depth l - r: V = -m2 g (l - r).
Lagrange: (m1 + m2) r'' = -m2 g; tension from m1: m1 r'' = -S.
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m1, m2, l, g, r0, v0 = symbols("m1 m2 l g r0 v0", positive=True)
r = Function("r")(t)

L = (m1 + m2) * r.diff(t) ** 2 / 2 + m2 * g * (l - r)
eom = [Eq((m1 + m2) * r.diff(t, 2), -m2 * g)]
a = -m2 * g / (m1 + m2)
S_t = m1 * m2 * g / (m1 + m2)
solution = {"r": r0 + v0 * t + a * t**2 / 2}
