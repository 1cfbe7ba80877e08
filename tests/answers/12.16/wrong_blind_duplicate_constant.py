# expect: L=correct, eom=correct, conserved=partial
from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
L = m*R**2*(dot(theta)**2 + sin(theta)**2*dot(phi)**2)/2 + m*g*R*cos(theta)
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (theta, phi)]
p_phi = m*R**2*sin(theta)**2*dot(phi)
conserved = [p_phi, 2*p_phi]          # one constant written twice; the energy is missing
