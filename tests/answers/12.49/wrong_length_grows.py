# expect: L=incorrect, H=incorrect, hamilton=incorrect, H_minus_E=correct, H_conserved=correct, H_is_E=correct, E_conserved=correct, dE_dt=incorrect
# Sign of the pull lost: ell = l0 + k*t (the string paid out instead of pulled in).
from lagrade.answer import *

m, l0, k, g = parameters("m l0 k g")
theta, p_theta = coordinates("theta p_theta")
ell = l0 + k * t
L = m * (k**2 + ell**2 * dot(theta) ** 2) / 2 + m * g * ell * cos(theta)
H = p_theta**2 / (2 * m * ell**2) - m * k**2 / 2 - m * g * ell * cos(theta)
hamilton = [Eq(dot(theta), p_theta / (m * ell**2)), Eq(dot(p_theta), -m * g * ell * sin(theta))]
H_minus_E = -m * k**2
H_conserved = False
H_is_E = False
E_conserved = False
dE_dt = -m * k * (ell * dot(theta) ** 2 + g * cos(theta))
