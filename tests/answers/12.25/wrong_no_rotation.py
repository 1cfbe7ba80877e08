# expect: L=incorrect, a=incorrect
# Forgot the rotational kinetic energy of the rolling sphere (treated it as a sliding block).
from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
L = M * dot(s) ** 2 / 2 + M * g * s * sin(theta)
a = g * sin(theta)
