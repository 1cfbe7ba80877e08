# expect: H=correct, hamilton=correct, H_F=correct, hamilton_F=correct
# A special case where the book names no force (issue 44): checked for the force it states, H, hamilton earn full marks.
# The free particle (V = 0), the case the problem states for answers without V(x).
from sympy import Eq, Function, symbols

t = symbols("t")
m, F = symbols("m F")
x, p_x = Function("x")(t), Function("p_x")(t)

H = p_x**2 / (2 * m)
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), 0)]
H_F = p_x**2 / (2 * m) - F * x
hamilton_F = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), F)]
