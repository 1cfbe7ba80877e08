# expect: L=incorrect, a=incorrect
# Gravity component along the slope taken as g*cos(theta), and the sign of V flipped in L.
from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
L = Rational(7, 10) * M * dot(s) ** 2 - M * g * s * sin(theta)
a = 5 * g * cos(theta) / 7
