# expect: L=incorrect, H=incorrect, H_conserved=correct, dH_dt=incorrect, H_is_E=incorrect, eom=incorrect
# exp(-t/tau) written as exp(-tau*t), and "time-dependent H cannot be the energy".
from lagrade.answer import *

m, k, tau = parameters("m k tau")
x, p_x = coordinates("x p_x")
L = m * dot(x) ** 2 / 2 - k * exp(-tau * t) / x
H = p_x**2 / (2 * m) + k * exp(-tau * t) / x
H_conserved = False
dH_dt = -k * tau * exp(-tau * t) / x
H_is_E = False
eom = [Eq(m * dot(x, 2), k * exp(-tau * t) / x**2)]
