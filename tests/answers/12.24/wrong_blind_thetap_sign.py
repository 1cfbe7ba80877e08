# expect: L=correct, eom=correct, eom_small=correct, omega0=correct, theta_p=incorrect
from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
L = m*(l**2*dot(theta)**2 - 2*a*omega*l*sin(omega*t)*cos(theta)*dot(theta))/2 + m*g*l*cos(theta)
eom = [l*dot(theta, 2) + g*sin(theta) - a*omega**2*cos(omega*t)*cos(theta)]
eom_small = [l*dot(theta, 2) + g*theta - a*omega**2*cos(omega*t)]
omega0 = sqrt(g/l)
theta_p = a*omega**2*cos(omega*t)/(l*omega**2 - g)
H_conserved = False
H_is_E = False
