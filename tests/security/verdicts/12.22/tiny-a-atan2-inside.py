# target: a
# family: tiny
# expect: no-credit
# why: a_m1 times atan2(m1*(1 + eps), m1 - m2)/atan2(m1, m1 - m2), eps = (m1*m2/(m1 + m2)**2)**200: the rule evaluates atan2 (two arguments) whole and never weighs inside it
from sympy import *
m1, m2, m3, m4, g = symbols("m1 m2 m3 m4 g", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
eps = (m1*m2/(m1 + m2)**2)**200
a = {"m1": (g - S/m1)*atan2(m1*(1 + eps), m1 - m2)/atan2(m1, m1 - m2), "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
