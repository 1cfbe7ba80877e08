# expect: L=incorrect, eom=incorrect, N_w=incorrect, leave_angle=correct
# Rotational kinetic energy about the centre forgotten: T = M*l**2*theta'**2/8, so theta'' = -2*g*cos(theta)/l and
# N_w = M*cos(theta)*(g*sin(theta) - l*theta'**2/2). (The leave condition sin(theta) = 2*sin(theta0)/3 does not
# depend on the moment of inertia, so this student still gets the angle right.)
from lagrade.answer import *

M, l, g = parameters("M l g")
theta0 = Symbol("theta0")
theta = coordinates("theta")
thd = dot(theta)
L = M * l**2 * thd**2 / 8 - M * g * l * sin(theta) / 2
eom = [Eq(dot(theta, 2), -2 * g * cos(theta) / l)]
N_w = M * cos(theta) * (g * sin(theta) - l * thd**2 / 2)
leave_angle = asin(2 * sin(theta0) / 3)
