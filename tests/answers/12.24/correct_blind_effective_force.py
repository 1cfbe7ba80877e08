from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
# the cross term -m*a*omega*l*sin(omega*t)*cos(theta)*theta' equals
# -d/dt(m*a*omega*l*sin(omega*t)*sin(theta)) + m*a*omega**2*l*cos(omega*t)*sin(theta): keep only the force term
L = m*l**2*dot(theta)**2/2 + m*a*omega**2*l*cos(omega*t)*sin(theta) + m*g*l*cos(theta)
eom = [Eq(m*l**2*dot(theta, 2), m*a*omega**2*l*cos(omega*t)*cos(theta) - m*g*l*sin(theta))]
eom_small = [Eq(dot(theta, 2), -g*theta/l + a*omega**2*cos(omega*t)/l)]
omega0 = sqrt(g/l)
theta_p = a*omega**2*cos(omega*t)/(g - l*omega**2)
H_conserved = False
H_is_E = False
