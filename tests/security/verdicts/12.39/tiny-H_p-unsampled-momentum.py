# target: H_p
# family: tiny
# expect: no-credit
# why: H' + k*exp(-100*(p_phip + 1)), huge for p_phip < -1: the negligible-part rule draws momenta from [-1.5, 1.5] (where the term dominates), the comparison uses the true momenta p_phip = m*r**2*(phip' + omega) >= -0.8 (where it is below 1e-14 of the rates, and below ball arithmetic's 128 bits at the three exact states)
from sympy import Function, symbols, exp
m, k, omega = symbols("m k omega", positive=True)
r, phip = symbols("r phip")
p_r, p_phip = symbols("p_r p_phip")
V = Function("V")
H_p = p_r**2/(2*m) + p_phip**2/(2*m*r**2) - omega*p_phip + V(r) + k*exp(-100*(p_phip + 1))
