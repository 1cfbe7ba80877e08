# expect: H=correct, hamilton=partial
# p' = +dH/dx: Hamilton's second equation has a minus sign.
from lagrade.answer import *

m, k, eps = parameters("m k eps")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m) + k * x**2 / 2 + eps * x**4 / 4
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), k * x + eps * x**3)]
