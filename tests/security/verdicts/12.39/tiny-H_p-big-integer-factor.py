# target: H_p
# family: tiny
# expect: no-credit
# why: V(r) times (r + 10**11)/(m + 10**11): a force 1e-11*V(r) added, in a factor of atoms the rule never weighs
from sympy import Function, symbols
m, k, omega = symbols("m k omega", positive=True)
r, phip = symbols("r phip")
p_r, p_phip = symbols("p_r p_phip")
V = Function("V")
H_p = p_r**2/(2*m) + p_phip**2/(2*m*r**2) - omega*p_phip + V(r)*(r + 10**11)/(m + 10**11)
