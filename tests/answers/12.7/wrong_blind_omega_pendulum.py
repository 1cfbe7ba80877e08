# expect: L=correct, eom=correct, omega=incorrect
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
L = m*(dot(r)**2 + r**2*dot(theta)**2)/2 + m*g*r*cos(theta) - k*(r - l0)**2/2
eom = [m*dot(r, 2) - m*r*dot(theta)**2 - m*g*cos(theta) + k*(r - l0),
       m*r**2*dot(theta, 2) + 2*m*r*dot(r)*dot(theta) + m*g*r*sin(theta)]
omega = sqrt(g/l0)
