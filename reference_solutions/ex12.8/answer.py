"""Exercise 12.8: Example 12.5 (block on a free wedge) with Hamilton's equations.

L = (M + m) x1'^2/2 + m x2'^2/2 + m c x1' x2' + m g s x2   (c = cos th, s = sin th)
p_x1 = (M + m) x1' + m c x2',  p_x2 = m c x1' + m x2'.
Inverting (det = m (M + m) - m^2 c^2 = m (M + m s^2)):
x1' = (p_x1 - c p_x2)/(M + m s^2),  x2' = ((M + m) p_x2 - m c p_x1)/(m (M + m s^2)).
H = (m p_x1^2 - 2 m c p_x1 p_x2 + (M + m) p_x2^2)/(2 m (M + m s^2)) - m g s x2  (= E).
p_x1' = -dH/dx1 = 0: x1 is cyclic, p_x1 (total horizontal momentum) is constant.
p_x2' = -dH/dx2 = m g s.
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, g, theta = symbols("m M g theta", positive=True)
x1, x2 = Function("x1")(t), Function("x2")(t)
p_x1, p_x2 = Function("p_x1")(t), Function("p_x2")(t)
c, s = cos(theta), sin(theta)
D = M + m * s**2

H = (m * p_x1**2 - 2 * m * c * p_x1 * p_x2 + (M + m) * p_x2**2) / (2 * m * D) - m * g * s * x2
hamilton = [
    Eq(x1.diff(t), (p_x1 - c * p_x2) / D),
    Eq(x2.diff(t), ((M + m) * p_x2 - m * c * p_x1) / (m * D)),
    Eq(p_x1.diff(t), 0),
    Eq(p_x2.diff(t), m * g * s),
]
cyclic = ["x1"]
conserved = [(M + m) * x1.diff(t) + m * c * x2.diff(t)]
