# expect: H=incorrect, hamilton=partial
# The kinetic energy of the vertical motion is forgotten: v**2 = a**2*theta'**2 only.
from lagrade.answer import *

m, a, k, g = parameters("m a k g")
theta, p_theta = coordinates("theta p_theta")
H = p_theta**2 / (2 * m * a**2) + m * g * k * theta
hamilton = [Eq(dot(theta), p_theta / (m * a**2)), Eq(dot(p_theta), -m * g * k)]
