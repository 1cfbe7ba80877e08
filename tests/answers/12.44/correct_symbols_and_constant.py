# Plain symbols in H, with a constant energy offset; Hamilton's equations as expressions meaning = 0.
from sympy import Function, Symbol, symbols

t = Symbol("t")
m, k, eps = symbols("m k eps")
x, p = symbols("x p_x")
H = p**2 / (2 * m) + k * x**2 / 2 + eps * x**4 / 4 + k * m

X, P = Function("x")(t), Function("p_x")(t)
hamilton = [P.diff(t) + k * X + eps * X**3, X.diff(t) - P / m]
