# expect: L=incorrect, eom=incorrect, a=incorrect
from lagrade.answer import *

m1, m2, m3, g, l_a, l_b = parameters("m1 m2 m3 g l_a l_b")
x1, x2 = coordinates("x1 x2")
# m3 placed at l_a - x1 + l_b + x2: the movable pulley's string constraint with the wrong sign
y1, y2, y3 = x1, l_a - x1 + x2, l_a - x1 + l_b + x2
L = sum(mi*yi.diff(t)**2/2 + mi*g*yi for mi, yi in ((m1, y1), (m2, y2), (m3, y3)))
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (x1, x2)]
sol = solve([e.subs({dot(x1, 2): Symbol("A1"), dot(x2, 2): Symbol("A2")}) for e in eom], [Symbol("A1"), Symbol("A2")])
A1, A2 = sol[Symbol("A1")], sol[Symbol("A2")]
a = {"m1": A1, "m2": A2 - A1, "m3": A2 - A1}
