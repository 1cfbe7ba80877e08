# The elevator-frame formulation throughout, in the catalogue's names: L2 = m*x'**2/2 - k*x**2/2 + m*(g + a0)*x
# (L of the ground frame minus d/dt(-m*a0*t*x) and a function of t), p_x = m*x', H2 = p_x**2/(2m) + k x**2/2
# - m (g + a0) x: no explicit t, so H2 is conserved, and it is T + V of L2 (the energy in the elevator frame).
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
L = m * dot(x) ** 2 / 2 - k * x**2 / 2 + m * (g + a0) * x
eom = [Eq(m * dot(x, 2), m * (g + a0) - k * x)]
H = p_x**2 / (2 * m) + k * x**2 / 2 - m * (g + a0) * x
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), m * (g + a0) - k * x)]
H_conserved = True
H_is_E = True
period = 2 * pi * sqrt(m / k)
