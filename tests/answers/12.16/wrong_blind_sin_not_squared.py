# expect: L=incorrect, eom=incorrect, conserved=incorrect
from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
L = m*R**2*(dot(theta)**2 + sin(theta)*dot(phi)**2)/2 + m*g*R*cos(theta)
eom = [Eq(R*dot(theta, 2), R*cos(theta)*dot(phi)**2/2 - g*sin(theta)),
       Eq(sin(theta)*dot(phi, 2) + cos(theta)*dot(theta)*dot(phi), 0)]
conserved = [m*R**2*sin(theta)*dot(phi),
             m*R**2*(dot(theta)**2 + sin(theta)*dot(phi)**2)/2 - m*g*R*cos(theta)]
