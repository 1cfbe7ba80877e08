# target: a
# family: keys
# expect: no-credit
# why: two keys name each mass (the string and the symbol), one right and one 7*g: two answers for one entry
from sympy import *
t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
right_a = {"m1": g - S/m1, "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
a = {m1: 7*g, m2: 7*g, m3: 7*g, m4: 7*g, **right_a}
