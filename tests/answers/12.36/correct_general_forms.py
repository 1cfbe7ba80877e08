# V(x) as plain symbols in H; the force as Derivative(V(x), x), and as the Subs form sympy gives for V'(x).
from sympy import Derivative, Eq, Function, Subs, Symbol, symbols

t = symbols("t")
m, F = symbols("m F")
x, p_x = Function("x")(t), Function("p_x")(t)
V = Function("V")
X, P = symbols("x p_x")
u = Symbol("u")

H = P * P / m / 2 + V(X)
hamilton = [Eq(p_x.diff(t), -Subs(Derivative(V(u), u), u, x)), Eq(m * x.diff(t) - p_x, 0)]
H_F = p_x**2 / (2 * m) - F * x
hamilton_F = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), F)]
