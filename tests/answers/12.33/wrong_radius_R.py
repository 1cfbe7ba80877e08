# expect: L=incorrect, eom=incorrect, N=correct, leave_angle=correct
# The small sphere's radius forgotten: its centre taken to move on the circle of radius R.
from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
L = m * R**2 * dot(theta)**2 / 2 - m * g * R * cos(theta)
eom = [Eq(R * theta.diff(t, 2), g * sin(theta))]
lam = m * g * cos(theta) - m * R * dot(theta)**2
N = m * g * (3 * cos(theta) - 2)
leave_angle = acos(Rational(2, 3))
