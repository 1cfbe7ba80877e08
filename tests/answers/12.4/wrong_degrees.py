# expect: leave_angle=incorrect, N=correct, solution=correct
# Gives the leave angle in degrees (48.19 degrees) instead of radians.
from lagrade.answer import *

m, R, g, theta0 = parameters("m R g theta0")
theta = symbols("theta")
solution = {"theta": 4 * atan(tan(theta0 / 4) * exp(sqrt(g / R) * t))}
N = m * g * (3 * cos(theta) - 2)
leave_angle = 180 * acos(Rational(2, 3)) / pi
