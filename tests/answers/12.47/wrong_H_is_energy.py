# expect: L=correct, eom=correct, H=incorrect, hamilton=partial, period=correct, H_conserved=correct, H_is_E=incorrect
# H written as T + V in the momentum: here H = E + a0*t*p_x, and x' = p_x/m + a0*t (not p_x/m).
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
L = m * (a0 * t - dot(x)) ** 2 / 2 - k * x**2 / 2 - m * g * (a0 * t**2 / 2 - l0 - x)
eom = [Eq(dot(x, 2), g + a0 - k * x / m)]
H = p_x**2 / (2 * m) + k * x**2 / 2 + m * g * (a0 * t**2 / 2 - l0 - x)
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), m * g - k * x)]
period = 2 * pi * sqrt(m / k)
H_conserved = False
H_is_E = True
