# expect: L=incorrect, a=incorrect
# Used the moment of inertia of a solid cylinder (M R^2/2) instead of a solid sphere (2 M R^2/5).
from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
L = Rational(3, 4) * M * dot(s) ** 2 + M * g * s * sin(theta)
a = 2 * g * sin(theta) / 3
