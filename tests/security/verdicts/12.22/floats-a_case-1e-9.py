# target: a_case
# family: floats
# expect: no-credit
# why: every acceleration is 1.000000001 times the right one: off by exactly 1e-9
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)

right_case = {"m1": -Rational(23, 25)*g, "m2": g/25, "m3": Rational(9, 25)*g, "m4": Rational(13, 25)*g}

a_case = {k: Float("1.000000001")*v for k, v in right_case.items()}
