# expect: L=incorrect, H=incorrect, H_conserved=correct, dH_dt=incorrect, H_is_E=correct, eom=incorrect
from lagrade.answer import *

m, k, tau = parameters("m k tau")
x = coordinates("x")
p_x = momenta("p_x")
L = m*dot(x)**2/2 + k*exp(-t/tau)/x
H = p_x**2/(2*m) - k*exp(-t/tau)/x
H_conserved = False
dH_dt = k*exp(-t/tau)/(tau*x)
H_is_E = True
eom = [Eq(m*dot(x, 2), -k*exp(-t/tau)/x**2)]
