# expect: H=correct, hamilton=correct, H_F=correct, hamilton_F=correct
# A special case where the book names no force (issue 44): checked for the force it states, H, hamilton earn full marks.
# Equivalent forms: momenta as plain symbols in H, H with a constant added, equations scaled and reordered.
from lagrade.answer import *

m, F = parameters("m F")
x, p_x = coordinates("x p_x")
px = symbols("p_x")
xs = symbols("x")
H = px**2 / (2 * m) + 5
hamilton = [Eq(p_x.diff(t), 0), Eq(m * x.diff(t), p_x)]
H_F = (px**2 - 2 * m * F * xs) / (2 * m)
hamilton_F = [p_x.diff(t) - F, m * x.diff(t) - p_x]
