# expect: L=correct, omega=correct
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
L = m*(dot(r)**2 + r**2*dot(theta)**2)/2 + m*g*r*cos(theta) - k*(r - l0)**2/2
eom = [Eq(m*dot(r, 2), m*g*cos(theta) - k*(r - l0)),
       Eq(r*dot(theta, 2) + 2*dot(r)*dot(theta), -g*sin(theta))]
omega = sqrt(k/m)
