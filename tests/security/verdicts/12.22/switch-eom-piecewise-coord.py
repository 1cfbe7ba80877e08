# target: eom
# family: switch
# expect: no-credit
# why: each equation is right only while the coordinate stays below 50 (then q'' = 0)
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

D = m1*m2*m3 + m1*m2*m4 + m1*m3*m4 + m2*m3*m4
X = g*(m1*m2*m3 + m1*m2*m4 - m1*m3*m4 - m2*m3*m4)/D
Y = 2*g*m3*m4*(m1 - m2)/D
Z = 2*g*m1*m2*(m3 - m4)/D

eom = [Eq(x.diff(t, 2), Piecewise((X, x < 50), (0, True))),
       Eq(y.diff(t, 2), Piecewise((Y, y < 50), (0, True))),
       Eq(z.diff(t, 2), Piecewise((Z, z < 50), (0, True)))]
