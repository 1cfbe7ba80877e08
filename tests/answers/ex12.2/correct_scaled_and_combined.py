# eom multiplied through by r**2 and written as "= 0"; L with 1/r written r**-1;
# conserved quantities combined (2*p_theta, E + p_theta): functionally the same constants.
from sympy import Function, symbols

t = symbols("t")
m, k = symbols("m k")
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

L = m * rd**2 / 2 + m * r**2 * thd**2 / 2 - k * r**-1
eom = [m * r**2 * r.diff(t, 2) - m * r**3 * thd**2 - k,
       r * theta.diff(t, 2) + 2 * rd * thd]
Q = {"theta": 0, "r": k * r**-2}
E = m * (rd**2 + r**2 * thd**2) / 2 + k / r
conserved = [2 * m * r**2 * thd, E + m * r**2 * thd]
bound_orbits = False
