# H with plain symbols for the coordinates and momenta; conserved written with the momentum symbols
# (L_z = x p_y - y p_x, and H itself); Hamilton's equations in another order.
from sympy import Eq, Function, Symbol, sqrt, symbols

t = Symbol("t")
m, k = symbols("m k")
X, Y, PX, PY = symbols("x y p_x p_y")
H = (PX**2 + PY**2) / (2 * m) - k / sqrt(X**2 + Y**2)

x, y = Function("x")(t), Function("y")(t)
p_x, p_y = Function("p_x")(t), Function("p_y")(t)
r3 = (x**2 + y**2) ** (3 / 2)
hamilton = [Eq(p_y.diff(t), -k * y / r3), Eq(p_x.diff(t), -k * x / r3),
            Eq(y.diff(t), p_y / m), Eq(x.diff(t), p_x / m)]
cyclic = []
conserved = [X * PY - Y * PX, H]
