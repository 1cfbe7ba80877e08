# expect: L=incorrect, S_t=incorrect
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0 = symbols("r0")
r, phi, theta = coordinates("r phi theta")
# took the hanging length to be r instead of l - r
L = m1*(dot(r)**2 + r**2*dot(phi)**2)/2 + m2*(dot(r)**2 + r**2*dot(theta)**2)/2 + m2*g*r*cos(theta)
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (r, phi, theta)]
a = {"r": (m1*r*dot(phi)**2 + m2*r*dot(theta)**2 + m2*g*cos(theta))/(m1 + m2),
     "phi": -2*dot(r)*dot(phi)/r,
     "theta": -(2*dot(r)*dot(theta) + g*sin(theta))/r}
S_t = m1*m2*(r*dot(phi)**2 - g*cos(theta) - r*dot(theta)**2)/(m1 + m2)
conserved = [m1*r**2*dot(phi), (m1 + m2)*dot(r)**2/2 + m1*r**2*dot(phi)**2/2 + m2*r**2*dot(theta)**2/2 - m2*g*r*cos(theta)]
omega = [sqrt(3*m2*g/((m1 + m2)*r0)), sqrt(g/r0)]
