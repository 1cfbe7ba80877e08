# The usual slips: H taken as T + V; the equilibrium upside down.
from lagrade.answer import *

m, R, g, omega = parameters("m R g omega")
theta = coordinates("theta")
p_theta = momenta("p_theta")

L = m*R**2*(dot(theta)**2 + omega**2*sin(theta)**2)/2 + m*g*R*cos(theta)
eom = [Eq(dot(theta, 2), omega**2*sin(theta)*cos(theta) - g/R*sin(theta))]
H = p_theta**2/(2*m*R**2) + m*R**2*omega**2*sin(theta)**2/2 - m*g*R*cos(theta)
equilibrium = Eq(cos(theta), omega**2*R/g)
