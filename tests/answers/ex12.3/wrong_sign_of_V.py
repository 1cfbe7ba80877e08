# expect: L=incorrect, eom=incorrect, a=correct
# V = +g*sum(m_i*depth_i): depths are measured downward, so V must be -g*sum(m_i*depth_i).
from sympy import Function, diff, symbols

t = symbols("t")
m1, m2, m3, g, l_a, l_b = symbols("m1 m2 m3 g l_a l_b")
x1, x2 = Function("x1")(t), Function("x2")(t)
v1, v2 = x1.diff(t), x2.diff(t)
L = m1 / 2 * v1**2 + m2 / 2 * (v2 - v1) ** 2 + m3 / 2 * (v1 + v2) ** 2 \
    - g * (m1 * x1 + m2 * (l_a - x1 + x2) + m3 * (l_a + l_b - x1 - x2))
eom = [diff(diff(L, q.diff(t)), t) - diff(L, q) for q in (x1, x2)]
D = m1 * m2 + m1 * m3 + 4 * m2 * m3
a1 = g * (m1 * m2 + m1 * m3 - 4 * m2 * m3) / D
a2 = 2 * g * m1 * (m2 - m3) / D
a = {"m1": a1, "m2": a2 - a1, "m3": -a1 - a2}
