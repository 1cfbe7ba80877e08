from lagrade.answer import *

m, l0, k, g = parameters("m l0 k g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
ell = l0 - k*t
xb, yb = ell*sin(theta), -ell*cos(theta)
T = m*(xb.diff(t)**2 + yb.diff(t)**2)/2
V = m*g*yb
L = T - V
H = p_theta**2/(2*m*ell**2) - m*k**2/2 - m*g*ell*cos(theta)
hamilton = [Eq(dot(theta), p_theta/(m*ell**2)), Eq(p_theta.diff(t), -m*g*ell*sin(theta))]
H_minus_E = -m*k**2
H_conserved = False
H_is_E = False
E_conserved = False
dE_dt = m*k*(ell*dot(theta)**2 + g*cos(theta))
