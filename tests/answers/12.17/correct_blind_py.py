from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0 = symbols("r0")
r, phi, theta = coordinates("r phi theta")
s = l - r                                    # hanging length
L = m1*(dot(r)**2 + r**2*dot(phi)**2)/2 + m2*(dot(r)**2 + s**2*dot(theta)**2)/2 + m2*g*s*cos(theta)
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (r, phi, theta)]
a = {"r": (m1*r*dot(phi)**2 - m2*s*dot(theta)**2 - m2*g*cos(theta))/(m1 + m2),
     "phi": -2*dot(r)*dot(phi)/r,
     "theta": (2*dot(r)*dot(theta) - g*sin(theta))/s}
S_t = m1*m2*(r*dot(phi)**2 + g*cos(theta) + s*dot(theta)**2)/(m1 + m2)
conserved = [m1*r**2*dot(phi), L.diff(dot(r))*dot(r) + L.diff(dot(phi))*dot(phi) + L.diff(dot(theta))*dot(theta) - L]
omega = [sqrt(3*m2*g/((m1 + m2)*r0)), sqrt(g/(l - r0))]
