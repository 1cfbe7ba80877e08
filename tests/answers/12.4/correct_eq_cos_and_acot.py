# Leave angle as the equation cos(theta) = 2/3, N with a half-angle identity, theta(t) via acot, dict keyed by the coordinate.
from lagrade.answer import *

m, R, g, theta0 = parameters("m R g theta0")
theta = coordinates("theta")

w = sqrt(g / R)
# tan(theta/4) = tan(theta0/4) e^{w t}  <=>  cot(theta/4) = cot(theta0/4) e^{-w t}
solution = {theta: 4 * acot(cot(theta0 / 4) * exp(-w * t))}
N = m * g * (1 - 6 * sin(theta / 2) ** 2)
leave_angle = Eq(cos(theta), Rational(2, 3))
