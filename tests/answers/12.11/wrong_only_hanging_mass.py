# expect: L=incorrect, eom=incorrect, a=incorrect, a_table=incorrect, S_t=incorrect
# Only the hanging mass's inertia counted (M's kinetic energy forgotten).
from lagrade.answer import *

m, M, g, alpha = parameters("m M g alpha")
x = coordinates("x")
L = m * dot(x) ** 2 / 2 + m * g * x - M * g * x * sin(alpha)
eom = [Eq(m * dot(x, 2), g * (m - M * sin(alpha)))]
a = g * (m - M * sin(alpha)) / m
a_table = g
S_t = M * g * sin(alpha)
