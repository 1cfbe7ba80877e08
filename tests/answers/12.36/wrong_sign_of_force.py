# expect: H=partial, hamilton=partial, H_F=incorrect, hamilton_F=partial
# A special case of the general function where the problem asks the general one (issue 33): H, hamilton, hamilton_F earn partial credit.
# H_F and hamilton_F are extras (the book asks a general V(x)): wrong, shown, not counted in the score (issue 33).
# The potential of the force written +F x (sign of F = -dV/dx lost), and p' = +dH/dx.
from lagrade.answer import *

m, F = parameters("m F")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m)
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), 0)]
H_F = p_x**2 / (2 * m) + F * x
hamilton_F = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -F)]
