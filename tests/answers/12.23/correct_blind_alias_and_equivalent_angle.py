from lagrade.answer import *

M, l, g = parameters("M l g")
theta0 = Symbol("theta0")
theta = coordinates("theta")
L = M*l**2*dot(theta)**2/6 - M*g*l*sin(theta)/2
eom = [Eq(dot(theta, 2), -3*g*cos(theta)/(2*l))]
lam_w = M*cos(theta)*(3*g*sin(theta) - 2*l*dot(theta)**2)/4
leave_angle = acos(sqrt(1 - 4*sin(theta0)**2/9))      # the same angle in (0, pi/2)
