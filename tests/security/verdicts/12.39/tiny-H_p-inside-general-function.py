# target: H_p
# family: tiny
# expect: no-credit
# why: V evaluated at r + (m*omega/(m + omega)**2)**200 instead of r: the rule treats V(...) as an unknown value and never weighs its argument
from sympy import Function, symbols
m, k, omega = symbols("m k omega", positive=True)
r, phip = symbols("r phip")
p_r, p_phip = symbols("p_r p_phip")
V = Function("V")
H_p = p_r**2/(2*m) + p_phip**2/(2*m*r**2) - omega*p_phip + V(r + (m*omega/(m + omega)**2)**200)
