# expect: L=incorrect, eom=correct
# The kinetic energy is written m*(x1'**2 + x2'**2) without the 1/2; the equations were then done right from F = ma.
from sympy import Eq, Function, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
x1, x2 = Function("x1")(t), Function("x2")(t)
L = m * (x1.diff(t) ** 2 + x2.diff(t) ** 2) - k * x1**2 / 2 - k * (x2 - x1) ** 2 / 2
eom = [Eq(m * x1.diff(t, 2), -2 * k * x1 + k * x2), Eq(m * x2.diff(t, 2), k * x1 - k * x2)]
