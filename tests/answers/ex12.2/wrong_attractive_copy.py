# expect: L=incorrect, eom=partial, Q=partial, conserved=partial, bound_orbits=incorrect
# The example's attractive case copied: V = -k/r, so the radial force has the wrong sign everywhere.
from sympy import Eq, Function, symbols

t = symbols("t")
m, k = symbols("m k")
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

L = m / 2 * (rd**2 + r**2 * thd**2) + k / r
eom = [Eq(r.diff(t, 2), r * thd**2 - k / (m * r**2)), Eq((r**2 * thd).diff(t), 0)]
Q = {"r": -k / r**2, "theta": 0}
conserved = [m * r**2 * thd, m / 2 * (rd**2 + r**2 * thd**2) - k / r]
bound_orbits = True
