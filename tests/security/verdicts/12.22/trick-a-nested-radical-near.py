# target: a
# family: trick
# expect: no-credit
# why: sqrt(3 + 2*sqrt(2)) - sqrt(2) is 1, and (sqrt(2) - 1)**40 is 5e-16 more
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)

a = {"m1": g*(sqrt(3 + 2*sqrt(2)) - sqrt(2) + (sqrt(2) - 1)**40) - S/m1, "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
