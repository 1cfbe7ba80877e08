# expect: L=correct, eom=correct, N_w=correct, leave_angle=incorrect
# The special case "released from the vertical" (sin(theta) = 2/3) given for every theta0.
from lagrade.answer import *

M, l, g = parameters("M l g")
theta = coordinates("theta")
thd = dot(theta)
L = M * l**2 * thd**2 / 6 - M * g * l * sin(theta) / 2
eom = [Eq(dot(theta, 2), -3 * g * cos(theta) / (2 * l))]
N_w = M * cos(theta) * (3 * g * sin(theta) / 4 - l * thd**2 / 2)
leave_angle = asin(Rational(2, 3))
