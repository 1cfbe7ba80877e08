# H from the mass matrix by sympy's inverse, plus a constant; conserved momentum with the energy added
# (both are constants); cyclic given as the coordinate itself.
from lagrade.answer import *

m, M, g, theta = parameters("m M g theta")
x1, x2 = coordinates("x1 x2")
p_x1, p_x2 = momenta("p_x1 p_x2")
A = Matrix([[M + m, m * cos(theta)], [m * cos(theta), m]])
p = Matrix([p_x1, p_x2])
H = (p.T * A.inv() * p)[0] / 2 - m * g * x2 * sin(theta) + 3 * m * g
v = A.inv() * p
hamilton = [Eq(x1.diff(t), v[0]), Eq(x2.diff(t), v[1]), Eq(p_x1.diff(t), 0), Eq(p_x2.diff(t), m * g * sin(theta))]
cyclic = [x1]
E = (M + m) * dot(x1)**2 / 2 + m * dot(x2)**2 / 2 + m * cos(theta) * dot(x1) * dot(x2) - m * g * x2 * sin(theta)
conserved = [(M + m) * dot(x1) + m * cos(theta) * dot(x2), E]
