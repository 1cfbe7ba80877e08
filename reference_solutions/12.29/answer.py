"""Problem 12.29: m1 on a smooth table, string over a solid-disk pulley (M, R), m2 hanging.

x = descent of m2; pulley angular velocity x'/R, I = M R^2/2.
T = (m1 + m2) x'^2/2 + I (x'/R)^2/2 = (m1 + m2 + M/2) x'^2/2, V = -m2 g x (+ const).
Lagrange: (m1 + m2 + M/2) x'' = m2 g.
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m1, m2, M, R, g, l = symbols("m1 m2 M R g l", positive=True)
x = Function("x")(t)
xd = x.diff(t)

I = M * R**2 / 2
L = (m1 + m2) * xd**2 / 2 + I * (xd / R) ** 2 / 2 + m2 * g * x
eom = [Eq((m1 + m2 + M / 2) * x.diff(t, 2), m2 * g)]
a = m2 * g / (m1 + m2 + M / 2)
