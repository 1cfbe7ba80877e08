# expect: L=incorrect, eom=incorrect, N=correct, leave_angle=incorrect
# Height measured downward by mistake (V = -m g rho cos theta): the top looks stable; and the rolling result 10/17 quoted.
from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
L = m * (R + r_s)**2 * dot(theta)**2 / 2 + m * g * (R + r_s) * cos(theta)
eom = [Eq(theta.diff(t, 2), -g * sin(theta) / (R + r_s))]
lam = m * g * cos(theta) - m * (R + r_s) * dot(theta)**2
N = m * g * (3 * cos(theta) - 2)
leave_angle = acos(Rational(10, 17))
