# target: a
# family: tiny
# expect: no-credit
# why: a_m1 times (m1 + X)/(m2 + X), X = ((m1 + m2)**2/(m1*m2))**200 >= 4**200: off by (m1 - m2)/X, small numbers only; the rule weighs X, never the atom m1 beside it
from sympy import *
m1, m2, m3, m4, g = symbols("m1 m2 m3 m4 g", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
X = ((m1 + m2)**2/(m1*m2))**200
a = {"m1": (g - S/m1)*(m1 + X)/(m2 + X), "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
