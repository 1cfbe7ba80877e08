# expect: L=incorrect, eom=incorrect, N=correct, leave_angle=correct
from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
L = m*R**2*dot(theta)**2/2 - m*g*R*cos(theta)          # the small sphere's centre is at R + r_s, not R
eom = [Eq(R*dot(theta, 2), g*sin(theta))]
lam = m*g*cos(theta) - m*R*dot(theta)**2
N = m*g*(3*cos(theta) - 2)
leave_angle = Eq(cos(theta), Rational(2, 3))
