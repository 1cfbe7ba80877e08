# expect: L=correct, H=incorrect, hamilton=partial, H_conserved=incorrect, E_conserved=incorrect, dE_dt=incorrect
# Length treated as constant once L is written: p_theta = m*l0**2*theta', and "no friction, so E is conserved".
from lagrade.answer import *

m, l0, k, g = parameters("m l0 k g")
theta, p_theta = coordinates("theta p_theta")
ell = l0 - k * t
L = m * (k**2 + ell**2 * dot(theta) ** 2) / 2 + m * g * ell * cos(theta)
H = p_theta**2 / (2 * m * l0**2) - m * g * ell * cos(theta)
hamilton = [Eq(dot(theta), p_theta / (m * l0**2)), Eq(dot(p_theta), -m * g * ell * sin(theta))]
H_minus_E = -m * k**2
H_conserved = True
H_is_E = False
E_conserved = True
dE_dt = 0
