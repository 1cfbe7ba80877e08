# expect: L=correct, eom=incorrect, eom_small=correct, omega0=correct, theta_p=correct, H_conserved=correct, H_is_E=correct
from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
L = m*(l**2*dot(theta)**2 - 2*a*omega*l*sin(omega*t)*cos(theta)*dot(theta) + a**2*omega**2*sin(omega*t)**2)/2 \
    + m*g*l*cos(theta)
eom = [Eq(l*dot(theta, 2) + g*sin(theta), a*omega**2*cos(omega*t)*sin(theta))]
eom_small = [Eq(l*dot(theta, 2) + g*theta, a*omega**2*cos(omega*t))]
omega0 = sqrt(g/l)
theta_p = a*omega**2*cos(omega*t)/(g - l*omega**2)
H_conserved = False
H_is_E = False
