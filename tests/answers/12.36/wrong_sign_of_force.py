# expect: H=correct, hamilton=correct, H_F=incorrect, hamilton_F=partial
# H, hamilton for the free particle: the book names no force, right for the force stated (issue 44); hamilton_F partial.
# H_F and hamilton_F are extras (the book asks no constant force): wrong, shown, not counted in the score (issue 33).
# The potential of the force written +F x (sign of F = -dV/dx lost), and p' = +dH/dx.
from lagrade.answer import *

m, F = parameters("m F")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m)
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), 0)]
H_F = p_x**2 / (2 * m) + F * x
hamilton_F = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -F)]
