# target: a
# family: honest
# expect: full-marks
# why: nothing: log(m1*m2) = log(m1) + log(m2) for positive masses
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)

a = {"m1": g*(log(m1*m2) - log(m1) - log(m2) + 1) - S/m1, "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
