# expect: L=correct, H=correct, hamilton=correct, H_minus_E=correct, dE_dt=incorrect
from lagrade.answer import *

m, l0, k, g = parameters("m l0 k g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
ell = l0 - k*t
L = m*(k**2 + ell**2*dot(theta)**2)/2 + m*g*ell*cos(theta)
H = p_theta**2/(2*m*ell**2) - m*k**2/2 - m*g*ell*cos(theta)
hamilton = [m*ell**2*dot(theta) - p_theta, p_theta.diff(t) + m*g*ell*sin(theta)]
H_minus_E = -m*k**2
H_conserved = False
H_is_E = False
E_conserved = False
dE_dt = -m*k*(ell*dot(theta)**2 + g*cos(theta))
