from lagrade.answer import *

m, k, tau = parameters("m k tau")
x = coordinates("x")
p_x = momenta("p_x")
V = k*exp(-t/tau)/x
L = m*dot(x)**2/2 - V
H = p_x**2/(2*m) + V
H_conserved = False
dH_dt = -V/tau          # partial derivative of H in t
H_is_E = True
eom = [Eq(m*dot(x, 2), k*exp(-t/tau)/x**2)]
