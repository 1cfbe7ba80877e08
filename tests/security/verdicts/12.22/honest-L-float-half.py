# target: L
# family: honest
# expect: full-marks
# why: nothing: 0.5 is exactly 1/2
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

L = (0.5*m1*(xd + yd)**2 + 0.5*m2*(xd - yd)**2 + 0.5*m3*(zd - xd)**2 + 0.5*m4*(xd + zd)**2
     + g*(m1*(x + y) + m2*(x + l1 - y) + m3*(l3 - x + z) + m4*(l3 - x + l2 - z)))
