# L with a total time derivative d/dt(M*g*R*s) added and a constant; a written as g*sin/(1 + 2/5).
from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
L = Rational(7, 10) * M * dot(s) ** 2 + M * g * s * sin(theta) + M * g * R * dot(s) + 3 * M * g * R
a = g * sin(theta) / (1 + Rational(2, 5))
