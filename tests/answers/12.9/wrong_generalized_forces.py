# expect: eom_a=partial
# Q_theta and Q_phi swapped.
from sympy import Eq, Function, sin, symbols

t = symbols("t")
m, Q_r, Q_theta, Q_phi = symbols("m Q_r Q_theta Q_phi")
r, th, ph = Function("r")(t), Function("theta")(t), Function("phi")(t)
L = m * (r.diff(t) ** 2 + r**2 * th.diff(t) ** 2 + r**2 * sin(th) ** 2 * ph.diff(t) ** 2) / 2
eom_a = [Eq(L.diff(q.diff(t)).diff(t) - L.diff(q), Q) for q, Q in ((r, Q_r), (th, Q_phi), (ph, Q_theta))]
