# target: a
# family: qdd
# expect: no-credit
# why: the accelerations are left as x'' + y'' etc.: nothing was solved, the grader fills q'' with the reference's values
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

a = {"m1": x.diff(t, 2) + y.diff(t, 2), "m2": x.diff(t, 2) - y.diff(t, 2),
     "m3": -x.diff(t, 2) + z.diff(t, 2), "m4": -x.diff(t, 2) - z.diff(t, 2)}
