# expect: L=correct, H=correct, H_conserved=incorrect, H_is_E=correct, eom=correct
from lagrade.answer import *

m, k, tau = parameters("m k tau")
x = coordinates("x")
p_x = momenta("p_x")
L = m*dot(x)**2/2 - k*exp(-t/tau)/x
H = p_x**2/(2*m) + k*exp(-t/tau)/x
H_conserved = True
dH_dt = -k*exp(-t/tau)/(tau*x)
H_is_E = True
eom = [m*dot(x, 2) - k*exp(-t/tau)/x**2]
