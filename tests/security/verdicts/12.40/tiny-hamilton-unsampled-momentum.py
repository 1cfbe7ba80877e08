# target: hamilton
# family: tiny
# expect: no-credit
# why: phip' = p_phip/(m*r**2) - omega - 100*omega*exp(-100*p_phip - 50), wrong (hugely) for p_phip < -1/2: the negligible-part rule draws momenta from [-1.5, 1.5], the comparison uses the true ones (p_phip >= -0.14 at its states, >= 1.2 along the motions), where the term is below 1e-14 of the rate
from sympy import Eq, Function, symbols, exp
t = symbols("t")
m, k, omega = symbols("m k omega", positive=True)
r, phip = Function("r")(t), Function("phip")(t)
p_r, p_phip = Function("p_r")(t), Function("p_phip")(t)
V = Function("V")
hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(phip.diff(t), p_phip / (m * r**2) - omega - 100*omega*exp(-100*p_phip - 50)),
    Eq(p_r.diff(t), p_phip**2 / (m * r**3) - V(r).diff(r)),
    Eq(p_phip.diff(t), 0),
]
