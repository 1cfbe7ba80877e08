# expect: L=correct, eom=correct, N=incorrect, leave_angle=incorrect
# The reaction taken as the static m g cos(theta) (centripetal term forgotten): falls off at 90 degrees.
from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
L = m * (R + r_s)**2 * dot(theta)**2 / 2 - m * g * (R + r_s) * cos(theta)
eom = [Eq(theta.diff(t, 2), g * sin(theta) / (R + r_s))]
lam = m * g * cos(theta)
N = m * g * cos(theta)
leave_angle = pi / 2
