# expect: L=incorrect, eom=incorrect, H=correct, hamilton=correct, period=incorrect, H_conserved=correct, H_is_E=correct
# Support acceleration entered with the wrong sign in the Lagrangian (mass velocity a0*t + x');
# the period made to depend on the effective gravity g + a0.
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
L = m * (a0 * t + dot(x)) ** 2 / 2 - k * x**2 / 2 - m * g * (a0 * t**2 / 2 - l0 - x)
eom = [Eq(dot(x, 2), g - a0 - k * x / m)]
H = p_x**2 / (2 * m) + a0 * t * p_x + k * x**2 / 2 + m * g * (a0 * t**2 / 2 - l0 - x)
hamilton = [Eq(dot(x), p_x / m + a0 * t), Eq(dot(p_x), m * g - k * x)]
period = 2 * pi * sqrt(m * (g + a0) / (k * g))
H_conserved = False
H_is_E = False
