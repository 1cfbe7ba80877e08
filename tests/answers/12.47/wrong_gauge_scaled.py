# expect: H=incorrect, hamilton=incorrect
# The Hamiltonian of 2*L (elevator frame): p_x = 2*m*x', H = p_x**2/(4*m) + k*x**2 - 2*m*(g + a0)*x. Its motion
# of x is the true one, but 2*L is no admissible Lagrangian (L = T - V fixes the scale), nor a gauge of one.
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
H = p_x**2 / (4 * m) + k * x**2 - 2 * m * (g + a0) * x
hamilton = [Eq(dot(x), p_x / (2 * m)), Eq(dot(p_x), 2 * m * (g + a0) - 2 * k * x)]
