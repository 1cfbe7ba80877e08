# L with a constant and a total derivative added; eom as an expression = 0, scaled; tension from M's side.
from lagrade.answer import *

m, M, g, alpha = parameters("m M g alpha")
x = coordinates("x")
L = (m + M) * dot(x) ** 2 / 2 + g * x * (m - M * sin(alpha)) + 3 * g + diff(x**2, t)
eom = 2 * (m + M) * dot(x, 2) - 2 * m * g + 2 * M * g * sin(alpha)
a = m * g / (m + M) - M * g * sin(alpha) / (m + M)
a_table = g / (1 + M / m)
S_t = M * (a + g * sin(alpha))
