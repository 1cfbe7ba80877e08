# expect: H=incorrect, hamilton=incorrect, H_F=incorrect, hamilton_F=partial
# H written with the velocity (m x'^2/2), and Newton's p' = F used for x' too.
from lagrade.answer import *

m, F = parameters("m F")
x, p_x = coordinates("x p_x")
H = m * x.diff(t)**2 / 2
hamilton = [Eq(x.diff(t), p_x), Eq(p_x.diff(t), p_x / m)]
H_F = m * x.diff(t)**2 / 2 - F * x
hamilton_F = [Eq(x.diff(t), p_x), Eq(p_x.diff(t), F)]
