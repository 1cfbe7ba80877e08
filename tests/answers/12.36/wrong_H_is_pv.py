# expect: H=incorrect, hamilton=partial, H_F=incorrect, hamilton_F=partial
# H taken as p x' (= p^2/m) without subtracting L, so x' = 2 p/m.
from lagrade.answer import *

m, F = parameters("m F")
x, p_x = coordinates("x p_x")
H = p_x**2 / m
hamilton = [Eq(x.diff(t), 2 * p_x / m), Eq(p_x.diff(t), 0)]
H_F = p_x**2 / m - F * x
hamilton_F = [Eq(x.diff(t), 2 * p_x / m), Eq(p_x.diff(t), F)]
