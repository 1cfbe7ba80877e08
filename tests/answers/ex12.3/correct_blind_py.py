from lagrade.answer import *

m1, m2, m3, g, l_a, l_b = parameters("m1 m2 m3 g l_a l_b")
x1, x2 = coordinates("x1 x2")
y1, y2, y3 = x1, l_a - x1 + x2, l_a - x1 + l_b - x2
L = sum(mi*yi.diff(t)**2/2 + mi*g*yi for mi, yi in ((m1, y1), (m2, y2), (m3, y3)))
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (x1, x2)]
D = m1*m2 + m1*m3 + 4*m2*m3
a = {"m1": g*(m1*m2 + m1*m3 - 4*m2*m3)/D,
     "m2": g*(m1*m2 - 3*m1*m3 + 4*m2*m3)/D,
     "m3": g*(m1*m3 - 3*m1*m2 + 4*m2*m3)/D}
