# target: a
# family: trick
# expect: no-credit
# why: sqrt(expand(P**2))/P with P = (3 - m1)(3 - m2)(3 - m3)(3 - m4)(3 - g) is sign(P): 1 in the box, -1 beyond
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
P = (3 - m1)*(3 - m2)*(3 - m3)*(3 - m4)*(3 - g)
switch = sqrt(expand(P**2))/P
a = {"m1": (g - S/m1)*switch, "m2": (g - S/m2)*switch, "m3": (g - S/m3)*switch, "m4": (g - S/m4)*switch}
