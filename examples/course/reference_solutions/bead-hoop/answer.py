"""Reference answer to bead-hoop: a bead on a hoop rotating about its vertical diameter."""

from lagrade.answer import *

m, R, g, omega = parameters("m R g omega")
theta = coordinates("theta")
p_theta = momenta("p_theta")

# the bead's velocity: R*theta' along the hoop, omega*R*sin(theta) around the vertical axis
L = m*R**2*(dot(theta)**2 + omega**2*sin(theta)**2)/2 + m*g*R*cos(theta)
eom = [Eq(dot(theta, 2), omega**2*sin(theta)*cos(theta) - g/R*sin(theta))]
H = p_theta**2/(2*m*R**2) - m*R**2*omega**2*sin(theta)**2/2 - m*g*R*cos(theta)
equilibrium = acos(g/(omega**2*R))
