# expect: L=correct, H=correct, H_conserved=incorrect, dH_dt=incorrect, H_is_E=correct, eom=correct
# "H is the energy, and a force from a potential conserves energy": the potential depends on t.
from lagrade.answer import *

m, k, tau = parameters("m k tau")
x, p_x = coordinates("x p_x")
L = m * dot(x) ** 2 / 2 - k * exp(-t / tau) / x
H = p_x**2 / (2 * m) + k * exp(-t / tau) / x
H_conserved = True
dH_dt = 0
H_is_E = True
eom = [Eq(m * dot(x, 2), k * exp(-t / tau) / x**2)]
