from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
L = m*R**2*(dot(theta)**2 + sin(theta)**2*dot(phi)**2)/2 + m*g*R*cos(theta)
eom = [Eq(dot(theta, 2), sin(theta)*cos(theta)*dot(phi)**2 - g/R*sin(theta)),
       Eq(dot(phi, 2), -2*cos(theta)*dot(theta)*dot(phi)/sin(theta))]
p_phi = m*R**2*sin(theta)**2*dot(phi)
E = m*R**2*(dot(theta)**2 + sin(theta)**2*dot(phi)**2)/2 - m*g*R*cos(theta)
conserved = [p_phi, E]
