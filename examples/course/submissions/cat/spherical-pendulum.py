# The bob's azimuthal speed taken as l*phi' (no sin(theta)), and what follows from it.
from lagrade.answer import *

m, l, g = parameters("m l g")
theta, phi = coordinates("theta phi")
p_theta, p_phi = momenta("p_theta p_phi")

L = m*l**2*(dot(theta)**2 + dot(phi)**2)/2 + m*g*l*cos(theta)
eom = [Eq(dot(theta, 2), -g/l*sin(theta)), Eq(dot(phi, 2), 0)]
cyclic = ["phi"]
conserved = [m*l**2*dot(phi)]
H = p_theta**2/(2*m*l**2) + p_phi**2/(2*m*l**2) - m*g*l*cos(theta)
