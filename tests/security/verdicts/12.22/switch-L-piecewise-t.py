# target: L
# family: switch
# expect: no-credit
# why: L is right only for t < 3 and 0 afterwards; the motion is compared over [0, 2]
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

T = m1/2*(xd + yd)**2 + m2/2*(xd - yd)**2 + m3/2*(zd - xd)**2 + m4/2*(xd + zd)**2
V = -g*(m1*(x + y) + m2*(x + l1 - y) + m3*(l3 - x + z) + m4*(l3 - x + l2 - z))

L = Piecewise((T - V, t < 3), (0, True))
