from lagrade.answer import *

m, k, tau = parameters("m k tau")
x = coordinates("x")
p_x = symbols("p_x")
V = k*exp(-t/tau)/x
L = m*dot(x)**2/2 - V
H = p_x**2/(2*m) + V
dH_dt = -k*exp(-t/tau)/(tau*x)
H_conserved = S.false             # sympy's booleans
H_is_E = Eq(H, p_x**2/(2*m) + V)  # evaluates to sympy's True
eom = [Eq(dot(x, 2), k*exp(-t/tau)/(m*x**2))]
