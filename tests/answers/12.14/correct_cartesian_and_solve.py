# L from the Cartesian bob positions, exact eom via euler_equations, omegas from det(K - w^2 M) = 0 solved by sympy.
from sympy import Function, Matrix, cos, sin, solve, sqrt, symbols
from sympy.calculus.euler import euler_equations

t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
x1, y1 = l1 * sin(th1), -l1 * cos(th1)
x2, y2 = x1 + l2 * sin(th2), y1 - l2 * cos(th2)
T = m1 / 2 * (x1.diff(t) ** 2 + y1.diff(t) ** 2) + m2 / 2 * (x2.diff(t) ** 2 + y2.diff(t) ** 2)
V = m1 * g * y1 + m2 * g * y2
L = T - V
eom_exact = euler_equations(L, [th1, th2], t)

M = Matrix([[(m1 + m2) * l1**2, m2 * l1 * l2], [m2 * l1 * l2, m2 * l2**2]])
K = Matrix([[(m1 + m2) * g * l1, 0], [0, m2 * g * l2]])
q = Matrix([th1, th2])
eom = list(M * q.diff(t, 2) + K * q)
W = symbols("W", positive=True)
omega = [sqrt(r) for r in solve((K - W * M).det(), W)]
