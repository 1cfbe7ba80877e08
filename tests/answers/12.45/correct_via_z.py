# Written through z = k*theta and the arc-length speed; Hamilton's equations reordered.
from lagrade.answer import *

m, a, k, g = parameters("m a k g")
theta, p_theta = coordinates("theta p_theta")
z = k * theta
s2 = a**2 + k**2
H = p_theta**2 / (2 * m * s2) + m * g * z
hamilton = [Eq(dot(p_theta), -diff(m * g * z, theta)), Eq(dot(theta), diff(H, p_theta))]
