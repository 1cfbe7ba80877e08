# target: H
# family: tiny
# expect: no-credit
# why: H' + k*exp(-100*(p_phip + 1)), huge for p_phip < -1: the negligible-part rule draws momenta from [-1.5, 1.5], the comparison uses the true momenta (p_phip >= -0.7 at its states), where the term is below every tolerance
from sympy import Function, symbols, exp
m, k, omega = symbols("m k omega", positive=True)
r, phip = symbols("r phip")
p_r, p_phip = symbols("p_r p_phip")
V = Function("V")
H = p_r**2/(2*m) + p_phip**2/(2*m*r**2) - omega*p_phip + V(r) + k*exp(-100*(p_phip + 1))
