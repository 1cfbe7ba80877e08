# target: a
# family: trick
# expect: no-credit
# why: exp(pi*sqrt(163)) is 262537412640768744 less 7.5e-13: the coefficient is 1 - 2.9e-30
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)

a = {"m1": g*exp(pi*sqrt(163))/262537412640768744 - S/m1, "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
