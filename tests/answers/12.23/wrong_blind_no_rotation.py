# expect: L=incorrect, eom=incorrect, N_w=incorrect, leave_angle=correct
from lagrade.answer import *

M, l, g = parameters("M l g")
theta0 = symbols("theta0")
theta = coordinates("theta")
L = M*l**2*dot(theta)**2/8 - M*g*l*sin(theta)/2      # forgot the rotation about the centre
eom = [Eq(dot(theta, 2), -2*g*cos(theta)/l)]
N_w = M*g*sin(theta)*cos(theta) - M*l*cos(theta)*dot(theta)**2/2
leave_angle = asin(2*sin(theta0)/3)
