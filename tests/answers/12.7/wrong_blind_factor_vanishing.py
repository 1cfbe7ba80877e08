# expect: L=correct, omega=correct, eom=incorrect
# eom: equations with a factor that vanishes inside the physical domain determine no motion there: no credit (issue 42, item 4)
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
L = m*(dot(r)**2 + r**2*dot(theta)**2)/2 + m*g*r*cos(theta) - k*(r - l0)**2/2
# the r-equation multiplied by the stretch (r - l0), which vanishes when the spring passes its natural length
eom = [Eq((r - l0)*(m*dot(r, 2) - m*r*dot(theta)**2 - m*g*cos(theta)), -k*(r - l0)**2),
       Eq(r*dot(theta, 2) + 2*dot(r)*dot(theta), -g*sin(theta))]
omega = sqrt(k/m)
