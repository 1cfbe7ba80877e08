# expect: H=correct, hamilton=correct, H_conserved=incorrect, H_is_E=incorrect
# H_conserved and H_is_E are extras (the book does not ask them): wrong, shown, not counted in the score (issue 33).
# The ground-frame H (explicitly time dependent, and E + a0*t*p_x) with the elevator frame's answers to the
# two questions: they are judged for the student's own H.
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
L = m * (a0 * t - dot(x)) ** 2 / 2 - k * x**2 / 2 - m * g * (a0 * t**2 / 2 - l0 - x)
eom = [Eq(dot(x, 2), g + a0 - k * x / m)]
H = p_x**2 / (2 * m) + a0 * t * p_x + k * x**2 / 2 + m * g * (a0 * t**2 / 2 - l0 - x)
hamilton = [Eq(dot(x), p_x / m + a0 * t), Eq(dot(p_x), m * g - k * x)]
H_conserved = True
H_is_E = True
period = 2 * pi * sqrt(m / k)
