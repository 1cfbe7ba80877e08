# expect: L=correct, eom=correct, Q=partial, conserved=correct
# Q_r confused with the "effective" radial force k/r^2 + m r theta'^2 (the centrifugal term is kinematic, not a force).
from sympy import Eq, Function, symbols

t = symbols("t")
m, k = symbols("m k")
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

L = m / 2 * (rd**2 + r**2 * thd**2) - k / r
eom = [Eq(m * r.diff(t, 2) - m * r * thd**2, k / r**2), Eq((m * r**2 * thd).diff(t), 0)]
Q = {"r": k / r**2 + m * r * thd**2, "theta": 0}
conserved = [m * r**2 * thd, m / 2 * (rd**2 + r**2 * thd**2) + k / r]
bound_orbits = False
