# expect: L=correct, eom=correct, N_w=incorrect, leave_angle=correct
from lagrade.answer import *

M, l, g = parameters("M l g")
theta0 = symbols("theta0")
theta = coordinates("theta")
L = M*l**2*dot(theta)**2/6 - M*g*l*sin(theta)/2
eom = [2*l*dot(theta, 2) + 3*g*cos(theta)]
N_w = M*l*cos(theta)*dot(theta)**2/2 - 3*M*g*sin(theta)*cos(theta)/4
leave_angle = Eq(sin(theta), 2*sin(theta0)/3)
