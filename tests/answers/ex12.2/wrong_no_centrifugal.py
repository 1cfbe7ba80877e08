# expect: L=incorrect, eom=incorrect, Q=correct, conserved=incorrect
# Transverse kinetic energy forgotten (T = m r'^2/2 + m theta'^2/2): no centrifugal term, no r^2 in p_theta.
from sympy import Eq, Function, symbols

t = symbols("t")
m, k = symbols("m k")
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

L = m / 2 * (rd**2 + thd**2) - k / r
eom = [Eq(m * r.diff(t, 2), k / r**2), Eq(theta.diff(t, 2), 0)]
Q = {"r": k / r**2, "theta": 0}
conserved = [m * thd, m / 2 * rd**2 + k / r]
bound_orbits = False
