# target: a
# family: trick
# expect: no-credit
# why: exp(-exp(60 - m1)) is below 1e-26 wherever a mass up to 2 is sampled, and 1/e at m1 = 60
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)

a = {"m1": g*(1 + exp(-exp(60 - m1))) - S/m1, "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
