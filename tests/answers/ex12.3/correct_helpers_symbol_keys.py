# Lagrange's equations from sympy's euler_equations, accelerations keyed by the mass symbols; L without the constant lengths.
from lagrade.answer import *
from sympy.calculus.euler import euler_equations

m1, m2, m3, g, l_a, l_b = parameters("m1 m2 m3 g l_a l_b")
x1, x2 = coordinates("x1 x2")
L = m1 / 2 * dot(x1) ** 2 + m2 / 2 * (dot(x2) - dot(x1)) ** 2 + m3 / 2 * (dot(x1) + dot(x2)) ** 2 \
    + g * (m1 * x1 + m2 * (x2 - x1) - m3 * (x1 + x2))
eom = euler_equations(L, [x1, x2], t)
D = m1 * m2 + m1 * m3 + 4 * m2 * m3
a1 = g * (m1 * m2 + m1 * m3 - 4 * m2 * m3) / D
a2 = 2 * g * m1 * (m2 - m3) / D
a = {m1: a1, m2: a2 - a1, m3: -a1 - a2}
