# target: eom
# family: roots
# expect: no-credit
# why: (q'' - Q)*(q'' - 7*g) = 0 also allows q'' = 7 g: the equations do not determine the motion
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

D = m1*m2*m3 + m1*m2*m4 + m1*m3*m4 + m2*m3*m4
X = g*(m1*m2*m3 + m1*m2*m4 - m1*m3*m4 - m2*m3*m4)/D
Y = 2*g*m3*m4*(m1 - m2)/D
Z = 2*g*m1*m2*(m3 - m4)/D

eom = [(x.diff(t, 2) - X)*(x.diff(t, 2) - 7*g),
       (y.diff(t, 2) - Y)*(y.diff(t, 2) - 7*g),
       (z.diff(t, 2) - Z)*(z.diff(t, 2) - 7*g)]
