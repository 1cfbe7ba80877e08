"""Problem 12.11: M on a smooth incline (alpha), string over the top pulley, m hanging; x = descent of m.

T = (m + M) x'^2/2, V = -m g x + M g x sin(alpha).  (m + M) x'' = g (m - M sin(alpha)).
Tension from m: m x'' = m g - S  ->  S = m M g (1 + sin(alpha))/(m + M).
"""
from sympy import Eq, Function, sin, symbols

t = symbols("t")
m, M, g, alpha = symbols("m M g alpha", positive=True)
x = Function("x")(t)

L = (m + M) * x.diff(t) ** 2 / 2 + m * g * x - M * g * x * sin(alpha)
eom = [Eq((m + M) * x.diff(t, 2), g * (m - M * sin(alpha)))]
a = g * (m - M * sin(alpha)) / (m + M)
a_table = a.subs(alpha, 0)
S_t = m * M * g * (1 + sin(alpha)) / (m + M)
