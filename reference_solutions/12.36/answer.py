"""Problem 12.36: Hamilton's equations for a point mass on a straight line.

L = m x'^2/2 - V(x); p = m x'; H = p x' - L = p^2/(2m) + V(x);
x' = dH/dp = p/m, p' = -dH/dx = -V'(x)   (the book's general force F(x) = -V'(x): parts H, hamilton).
Free particle: V = 0 -> p' = 0 (p constant, x = x0 + p t/m).  Constant force F: V = -F x -> p' = F
(parts H_F, hamilton_F).
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m, F = symbols("m F")
x, p_x = Function("x")(t), Function("p_x")(t)
V = Function("V")

H = p_x**2 / (2 * m) + V(x)
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -V(x).diff(x))]

H_F = p_x**2 / (2 * m) - F * x
hamilton_F = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), F)]
