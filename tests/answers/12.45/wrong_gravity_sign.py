# expect: H=incorrect, hamilton=partial
# V = -m*g*z with z up: the bead climbs the helix.
from lagrade.answer import *

m, a, k, g = parameters("m a k g")
theta, p_theta = coordinates("theta p_theta")
H = p_theta**2 / (2 * m * (a**2 + k**2)) - m * g * k * theta
hamilton = [Eq(dot(theta), p_theta / (m * (a**2 + k**2))), Eq(dot(p_theta), m * g * k)]
