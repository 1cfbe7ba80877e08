# V written with the string length: m2 hangs at depth x below the table top + constant pieces
# involving l; eom as an expression = 0 with a factor 2; a with the 2 cleared.
from lagrade.answer import *

m1, m2, M, R, g, l = parameters("m1 m2 M R g l")
x = coordinates("x")
theta_dot = dot(x) / R
L = m1 * dot(x) ** 2 / 2 + m2 * dot(x) ** 2 / 2 + M * R**2 / 4 * theta_dot**2 - (-m2 * g * x - m1 * g * l)
eom = 2 * (m1 + m2) * dot(x, 2) + M * dot(x, 2) - 2 * m2 * g
a = 2 * m2 * g / (2 * m1 + 2 * m2 + M)
