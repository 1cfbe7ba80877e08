# target: a
# family: tiny
# expect: no-credit
# why: a_m1 times (m1 + 10**11)/(m2 + 10**11), off by 1e-11*(m1 - m2) relative: a factor of atoms, never weighed
from sympy import *
m1, m2, m3, m4, g = symbols("m1 m2 m3 m4 g", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
N = 10**11
a = {"m1": (g - S/m1)*(m1 + N)/(m2 + N), "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
