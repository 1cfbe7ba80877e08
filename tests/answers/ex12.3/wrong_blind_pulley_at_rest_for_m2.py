# expect: L=incorrect, a=incorrect
from lagrade.answer import *

m1, m2, m3, g, l_a, l_b = parameters("m1 m2 m3 g l_a l_b")
x1, x2 = coordinates("x1 x2")
# forgot that the movable pulley moves in the kinetic energy of m2 and m3
L = m1*dot(x1)**2/2 + m2*dot(x2)**2/2 + m3*dot(x2)**2/2 + g*(m1*x1 + m2*(x2 - x1) - m3*(x1 + x2))
eom = [Eq(m1*dot(x1, 2), g*(m1 - m2 - m3)), Eq((m2 + m3)*dot(x2, 2), g*(m2 - m3))]
a1 = g*(m1 - m2 - m3)/m1
a2 = g*(m2 - m3)/(m2 + m3)
a = {"m1": a1, "m2": a2 - a1, "m3": -a1 - a2}
