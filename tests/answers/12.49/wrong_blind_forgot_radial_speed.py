# expect: L=correct, H=correct, hamilton=correct, H_minus_E=incorrect, H_is_E=incorrect
from lagrade.answer import *

m, l0, k, g = parameters("m l0 k g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
ell = l0 - k*t
T = m*ell**2*dot(theta)**2/2          # forgot the bob's radial speed k
V = -m*g*ell*cos(theta)
L = T - V
H = p_theta**2/(2*m*ell**2) - m*g*ell*cos(theta)
hamilton = [Eq(dot(theta), p_theta/(m*ell**2)), Eq(p_theta.diff(t), -m*g*ell*sin(theta))]
H_minus_E = 0*m
H_conserved = False
H_is_E = True
E_conserved = False
dE_dt = m*k*(ell*dot(theta)**2 + g*cos(theta))
