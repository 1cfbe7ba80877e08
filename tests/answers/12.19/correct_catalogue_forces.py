# Lagrange's equations derived with sympy, generalized forces Q_u, Q_v left as symbols on the right.
from lagrade.answer import *

m, A, F_x, F_y = parameters("m A F_x F_y")
u, v = coordinates("u v")
Q_u, Q_v = symbols("Q_u Q_v")
x, y = A * cosh(u) * cos(v), A * sinh(u) * sin(v)
T = m * (diff(x, t) ** 2 + diff(y, t) ** 2) / 2
L = T
eom = [Eq(diff(diff(L, dot(q)), t) - diff(L, q), Qq) for q, Qq in ((u, Q_u), (v, Q_v))]
Q = {"u": F_x * diff(x, u) + F_y * diff(y, u), "v": F_x * diff(x, v) + F_y * diff(y, v)}
