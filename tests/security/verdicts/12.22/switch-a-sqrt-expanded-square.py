# target: a
# family: switch
# expect: no-credit
# why: sqrt(m1**2 - 100*m1 + 2500)/(50 - m1) is sign(50 - m1) multiplied out: 1 where m1 is sampled, -1 beyond 50
from sympy import *
t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
right_a = {"m1": g - S/m1, "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
a = {k: v*sqrt(m1**2 - 100*m1 + 2500)/(50-m1) for k, v in right_a.items()}
