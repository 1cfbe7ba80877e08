# expect: H=correct, hamilton=partial, H_F=correct, hamilton_F=correct
# The force written as -V(x) instead of -V'(x).
from sympy import Eq, Function, symbols

t = symbols("t")
m, F = symbols("m F")
x, p_x = Function("x")(t), Function("p_x")(t)
V = Function("V")

H = p_x**2 / (2 * m) + V(x)
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -V(x))]
H_F = p_x**2 / (2 * m) - F * x
hamilton_F = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), F)]
