# expect: H=incorrect, hamilton=partial, H_conserved=incorrect
# Elevator-frame momentum p_x = m*x', but the inertial force is forgotten (gravity alone): right in no
# formulation; H_conserved is then judged for the ground-frame H.
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m) + k * x**2 / 2 - m * g * x
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), m * g - k * x)]
H_conserved = True
