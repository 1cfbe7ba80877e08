# eom given as the sum and the difference of Lagrange's equations; L plus d/dt(x1*x2) and a constant.
from sympy import Eq, Function, symbols

t = symbols("t")
m, k = symbols("m k")
x1, x2 = Function("x1")(t), Function("x2")(t)

L = m * (x1.diff(t) ** 2 + x2.diff(t) ** 2) / 2 - k * x1**2 / 2 - k * (x1 - x2) ** 2 / 2 \
    + (x1 * x2).diff(t) + 3 * k
# (x1) m x1'' = -2k x1 + k x2,  (x2) m x2'' = k x1 - k x2; add and subtract them
eom = [
    Eq(m * (x1.diff(t, 2) + x2.diff(t, 2)), -k * x1),
    Eq(m * (x1.diff(t, 2) - x2.diff(t, 2)), -3 * k * x1 + 2 * k * x2),
]
