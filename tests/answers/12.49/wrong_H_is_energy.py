# expect: H=correct, H_minus_E=incorrect, H_conserved=correct, H_is_E=incorrect, E_conserved=correct, dE_dt=correct
# H written as T + V in the momentum: it differs from the true H only by the constant m*k**2, which the H part
# cannot see (H is defined up to a function of t); the comparison parts H_minus_E and H_is_E catch it.
from lagrade.answer import *

m, l0, k, g = parameters("m l0 k g")
theta, p_theta = coordinates("theta p_theta")
ell = l0 - k * t
L = m * (k**2 + ell**2 * dot(theta) ** 2) / 2 + m * g * ell * cos(theta)
H = p_theta**2 / (2 * m * ell**2) + m * k**2 / 2 - m * g * ell * cos(theta)
hamilton = [Eq(dot(theta), p_theta / (m * ell**2)), Eq(dot(p_theta), -m * g * ell * sin(theta))]
H_minus_E = 0
H_conserved = False
H_is_E = True
E_conserved = False
dE_dt = m * k * (ell * dot(theta) ** 2 + g * cos(theta))
