from lagrade.answer import *

m1, m2, m3, g, l_a, l_b = parameters("m1 m2 m3 g l_a l_b")
x1, x2 = coordinates("x1 x2")
L = m1*dot(x1)**2/2 + m2*(dot(x2) - dot(x1))**2/2 + m3*(dot(x1) + dot(x2))**2/2 \
    + g*(m1*x1 + m2*(x2 - x1) - m3*(x1 + x2))
A1, A2 = symbols("A1 A2")
eqs = [(L.diff(dot(q)).diff(t) - L.diff(q)).subs({dot(x1, 2): A1, dot(x2, 2): A2}) for q in (x1, x2)]
sol = solve(eqs, [A1, A2])
eom = [Eq(dot(x1, 2), sol[A1]), Eq(dot(x2, 2), sol[A2])]
a = {m1: sol[A1], m2: sol[A2] - sol[A1], m3: -sol[A1] - sol[A2]}
