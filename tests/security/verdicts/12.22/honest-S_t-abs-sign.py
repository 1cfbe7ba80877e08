# target: S_t
# family: honest
# expect: full-marks
# why: nothing: Abs and sign of positive masses are the masses and 1
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

S = 4*g/(1/Abs(m1) + 1/Abs(m2) + 1/Abs(m3) + 1/Abs(m4))
S_t = {"S1": sign(m1)*S, "S2": sign(m2)*S, "S3": 2*sign(m3)*S}
