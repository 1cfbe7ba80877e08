# The elevator-frame Lagrangian (differs by a total time derivative plus a function of t) is a correct L;
# H and Hamilton's equations here are those of the ground-frame Lagrangian (shifted by a function of t).
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
L = m * dot(x) ** 2 / 2 - k * x**2 / 2 + m * (g + a0) * x
eom = [dot(x, 2) - (g + a0) + k * x / m]
H = (p_x + m * a0 * t) ** 2 / (2 * m) + k * x**2 / 2 - m * g * x - m * a0**2 * t**2 / 2
hamilton = [Eq(m * dot(x), p_x + m * a0 * t), Eq(dot(p_x) + k * x, m * g)]
period = 2 * pi / sqrt(k / m)
H_conserved = False  # H depends on t explicitly
H_is_E = False
