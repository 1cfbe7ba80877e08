# expect: eom=incorrect
# The generalized forces on the wrong side: d/dt(dL/dq') - dL/dq + Q_q = 0.
from lagrade.answer import *

m, A = parameters("m A")
u, v = coordinates("u v")
Q_u, Q_v = symbols("Q_u Q_v")
h2 = sinh(u) ** 2 + sin(v) ** 2
L = m * A**2 * h2 * (dot(u) ** 2 + dot(v) ** 2) / 2
eom = [Eq(diff(diff(L, dot(q)), t) - diff(L, q) + Qq, 0) for q, Qq in ((u, Q_u), (v, Q_v))]
