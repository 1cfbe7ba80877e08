# expect: L=correct, S_t=correct, conserved=correct, omega=correct
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0 = symbols("r0")
r, phi, theta = coordinates("r phi theta")
L = (m1 + m2)*dot(r)**2/2 + m1*r**2*dot(phi)**2/2 + m2*(l - r)**2*dot(theta)**2/2 + m2*g*(l - r)*cos(theta)
eom = [Eq((m1 + m2)*dot(r, 2), m1*r*dot(phi)**2 - m2*(l - r)*dot(theta)**2 - m2*g*cos(theta)),
       Eq(r*dot(phi, 2), -2*dot(r)*dot(phi)),
       Eq((l - r)*dot(theta, 2), -2*dot(r)*dot(theta) - g*sin(theta))]     # d/dt (l - r)^2 = -2 (l - r) r'
a = {"r": (m1*r*dot(phi)**2 - m2*(l - r)*dot(theta)**2 - m2*g*cos(theta))/(m1 + m2),
     "phi": -2*dot(r)*dot(phi)/r, "theta": -(2*dot(r)*dot(theta) + g*sin(theta))/(l - r)}
S_t = m1*m2*(r*dot(phi)**2 + g*cos(theta) + (l - r)*dot(theta)**2)/(m1 + m2)
conserved = [m1*r**2*dot(phi), (m1 + m2)*dot(r)**2/2 + m1*r**2*dot(phi)**2/2 + m2*(l - r)**2*dot(theta)**2/2 - m2*g*(l - r)*cos(theta)]
omega = [sqrt(3*m2*g/((m1 + m2)*r0)), sqrt(g/(l - r0))]
