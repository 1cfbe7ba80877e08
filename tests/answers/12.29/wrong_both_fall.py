# expect: L=incorrect, eom=incorrect, a=incorrect
# Gravity applied to m1 as well (it moves horizontally on the table).
from lagrade.answer import *

m1, m2, M, R, g, l = parameters("m1 m2 M R g l")
x = coordinates("x")
L = (m1 + m2 + M / 2) * dot(x) ** 2 / 2 + (m1 + m2) * g * x
eom = [Eq((m1 + m2 + M / 2) * dot(x, 2), (m1 + m2) * g)]
a = (m1 + m2) * g / (m1 + m2 + M / 2)
