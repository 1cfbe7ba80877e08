from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
X = a*cos(omega*t) + l*sin(theta)
Y = -l*cos(theta)
L = m*(X.diff(t)**2 + Y.diff(t)**2)/2 - m*g*Y
eom = [Eq(dot(theta, 2), (a*omega**2*cos(omega*t)*cos(theta) - g*sin(theta))/l)]
eom_small = [Eq(dot(theta, 2) + g/l*theta, a*omega**2/l*cos(omega*t))]
omega0 = sqrt(g/l)
theta_p = a*omega**2*cos(omega*t)/(g - l*omega**2)
H_conserved = False
H_is_E = False
