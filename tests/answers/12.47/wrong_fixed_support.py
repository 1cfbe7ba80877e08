# expect: L=incorrect, eom=incorrect, H=incorrect, hamilton=partial, period=correct, H_conserved=incorrect, H_is_E=incorrect
# The support is treated as fixed: the a0 disappears from the dynamics.
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
L = m * dot(x) ** 2 / 2 - k * x**2 / 2 + m * g * x
eom = [Eq(m * dot(x, 2), m * g - k * x)]
H = p_x**2 / (2 * m) + k * x**2 / 2 - m * g * x
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), m * g - k * x)]
period = 2 * pi * sqrt(m / k)
H_conserved = True
H_is_E = True
