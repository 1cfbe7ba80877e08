from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
b = R + r_s                      # centre-to-centre distance while in contact
L = m*b**2*dot(theta)**2/2 - m*g*b*cos(theta)
eom = [Eq(dot(theta, 2), g*sin(theta)/b)]
lam = m*g*cos(theta) - m*b*dot(theta)**2
N = m*g*(3*cos(theta) - 2)
leave_angle = acos(Rational(2, 3))
