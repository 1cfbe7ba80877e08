# expect: H=incorrect, hamilton=partial, eom=incorrect
from lagrade.answer import *

m, l, g = parameters("m l g")
theta, p_theta = coordinates("theta p_theta")
H = p_theta**2 / (2 * m * l**2) + m * g * l * cos(theta)
hamilton = [Eq(theta.diff(t), p_theta / (m * l**2)), Eq(p_theta.diff(t), m * g * l * sin(theta))]
eom = Eq(theta.diff(t, 2), g / l * sin(theta))
