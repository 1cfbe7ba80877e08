# expect: H=correct, hamilton=correct, H_conserved=incorrect, H_is_E=incorrect
# The elevator-frame H, but the answers to the two questions are the ground frame's: for this H (no explicit
# t, quadratic kinetic term) both are True.
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m) + k * x**2 / 2 - m * (g + a0) * x
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), m * (g + a0) - k * x)]
H_conserved = False
H_is_E = False
