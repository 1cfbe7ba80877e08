# L from the Cartesian position of the bob, with a total time derivative d(t*cos(theta))/dt added;
# dE/dt written with p_theta (allowed) instead of theta'.
from lagrade.answer import *

m, l0, k, g = parameters("m l0 k g")
theta, p_theta = coordinates("theta p_theta")
ell = l0 - k * t
X, Y = ell * sin(theta), -ell * cos(theta)
L = m * (diff(X, t) ** 2 + diff(Y, t) ** 2) / 2 - m * g * Y + diff(t * cos(theta), t)
H = p_theta**2 / (2 * m * ell**2) - m * k**2 / 2 - m * g * ell * cos(theta)
hamilton = [Eq(dot(p_theta), -diff(H, theta)), Eq(dot(theta), diff(H, p_theta))]
H_minus_E = -m * k**2
H_conserved = False
H_is_E = False
E_conserved = False
P = Symbol("p_theta")
dE_dt = k * P**2 / (m * ell**3) + m * g * k * cos(theta)
